// Ctrl-C and SIGTERM: long work stops at the next check, so that the output folder's
// destructor removes what was staged and nothing half-written is left behind.
#pragma once

namespace sphkern {

void install_interrupt_handlers();

// Throws Error(interrupted) once SIGINT or SIGTERM has arrived.
void throw_if_interrupted();

} // namespace sphkern
