// A plugin call that crashes (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) or calls exit():
// one line naming the plugin and its function, the staging output removed, exit 4 (the
// README's "plugin crashed or hung"). In a library host (the Python module), a crash instead
// returns to the call's recovery point, so that the call raises and the host goes on; exit()
// still ends the process (nothing can return from it). Outside a plugin call these signals go
// where they would have gone (the default action, or a library host's own handler).
#pragma once

#include <csetjmp>
#include <csignal>
#include <string>

namespace sphkern {

class PluginCall;

constexpr int fault_signal_count = 5;

// Installs the fault handlers. `host`, if given, receives the handlers that were in place;
// they get the signals that are not a plugin's, and give_back_fault_signals restores them.
void take_fault_signals(struct sigaction* host);
void give_back_fault_signals(const struct sigaction* host);

// Registers, once, the check that turns exit() inside a plugin call into exit 4 and one line.
void watch_exit_in_plugin_calls();

// True in a library host's own process (not in the command line, nor in a child it forked).
bool plugin_faults_recoverable();
// Where a crash inside a plugin call on this thread jumps back to (null: none); the jump's
// value is the signal. Set only around one call, with no C++ object made after sigsetjmp.
void set_recovery_point(sigjmp_buf* point) noexcept;
// Jumps to this thread's recovery point with `value` (a fault's signal, unblocked first, or
// plugin_exit_hook's exit_in_plugin_jump), where faults are recoverable and there is one; else returns.
// Async-signal-safe.
void jump_to_recovery_point(int value) noexcept;
// "crashed with signal 11 (SIGSEGV)".
std::string crash_description(int sig);

// Async-signal-safe: writes "sphkern: error: " and the parts as one line to stderr, removes
// the registered staging paths, and ends the process with `code` (no atexit handlers).
[[noreturn]] void end_process_with_line(int code, const char* const* parts, int count);

// "FILE: plugin kernel NAME <what> in W; nothing was written", then exit 4.
[[noreturn]] void end_for_plugin(const PluginCall& call, const char* what);

} // namespace sphkern
