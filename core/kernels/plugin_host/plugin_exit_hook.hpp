// exit() and _exit() called by a plugin's own code, redirected: the plugin's references to
// them (its GOT entries) point to sphkern's stand-ins once it is loaded. Inside a plugin call
// where faults are recoverable (a library host), the call returns to its recovery point and
// raises, as for a crash; anywhere else the real function runs (the command line then reports
// it through its exit() check, one line and exit 4). x86-64 Linux; elsewhere nothing is
// redirected and exit() keeps ending the process.
#pragma once

namespace sphkern {

// The value a recovery point receives for an exit() inside a plugin call: beyond any signal.
constexpr int exit_in_plugin_jump = 1024;

// Redirects the exit functions of the loaded library `handle` (a dlopen handle).
void redirect_plugin_exits(void* handle);

} // namespace sphkern
