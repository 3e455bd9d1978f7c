// The plugin host's share of the process, set up before the first plugin is probed or
// loaded: its fault handlers hooked into the signals sphkern takes (support/process/
// interruption.hpp), the exit() check and the watchdog of plugin calls.
#pragma once

namespace sphkern {

// Once per process; later calls do nothing.
void host_plugins();

} // namespace sphkern
