// A plugin call that crashes (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) or calls exit():
// one line naming the plugin and its function, the staging output removed, exit 4 (the
// README's "plugin crashed or hung"). Outside a plugin call these signals go where they
// would have gone (the default action, or a library host's own handler).
#pragma once

#include <csignal>

namespace sphkern {

class PluginCall;

constexpr int fault_signal_count = 5;

// Installs the fault handlers. `host`, if given, receives the handlers that were in place;
// they get the signals that are not a plugin's, and give_back_fault_signals restores them.
void take_fault_signals(struct sigaction* host);
void give_back_fault_signals(const struct sigaction* host);

// Registers, once, the check that turns exit() inside a plugin call into exit 4 and one line.
void watch_exit_in_plugin_calls();

// Async-signal-safe: writes "sphkern: error: " and the parts as one line to stderr, removes
// the registered staging paths, and ends the process with `code` (no atexit handlers).
[[noreturn]] void end_process_with_line(int code, const char* const* parts, int count);

// "FILE: plugin kernel NAME <what> in W; nothing was written", then exit 4.
[[noreturn]] void end_for_plugin(const PluginCall& call, const char* what);

} // namespace sphkern
