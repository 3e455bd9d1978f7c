// SIGINT, SIGTERM and SIGHUP: long work stops at the next check, so that staged
// output is removed and nothing half-written is left behind. A second signal ends
// the process at once, after removing the registered staging paths from inside the
// handler (async-signal-safe system calls only).
#pragma once

#include <filesystem>

namespace sphkern {

// Installs the handlers (again, after a plugin may have replaced them).
void install_interrupt_handlers();

// Throws Error(interrupted) once one of the signals has arrived.
void throw_if_interrupted();
bool interrupted();

// A path (file or folder) that a second signal must remove before the process dies.
// At most a few are registered at a time; each is removed again with unregister.
void register_staging_path(const std::filesystem::path& path);
void unregister_staging_path(const std::filesystem::path& path);

} // namespace sphkern
