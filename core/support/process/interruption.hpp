// SIGINT, SIGTERM and SIGHUP: long work stops at the next check, so that staged
// output is removed and nothing half-written is left behind. A second signal ends
// the process at once, after removing the registered staging paths from inside the
// handler (async-signal-safe system calls only).
#pragma once

#include <csignal>
#include <filesystem>

namespace sphkern {

// Handlers a layer above adds to the ones taken here (the plugin host's, for the fault
// signals): installed wherever the interrupt handlers are, `saved` receiving up to
// max_hooked_signals handlers that were in place, and given back with them.
constexpr int max_hooked_signals = 8;
struct SignalHook {
    void (*take)(struct sigaction* saved) = nullptr;
    void (*give_back)(const struct sigaction* saved) = nullptr;
};
// Once per process; where the handlers are already sphkern's, the hook takes its signals now.
void set_signal_hook(SignalHook hook);

// Installs the handlers for a program that owns its process (the command line): from now on
// a second signal ends it at once.
void install_interrupt_handlers();

// Whether sphkern owns its process (the command line), not a library host's guest (Python).
bool process_is_owned();

// Takes the handlers back after a library's constructors may have replaced them, where
// sphkern has them: in the command line, or inside an InterruptScope. Elsewhere (a Python
// interpreter between calls) the host's handlers stay.
void restore_interrupt_handlers();

// For a library host (the Python module), around one call: SIGINT, SIGTERM and SIGHUP set
// sphkern's flag, so that long work stops at its next check with Error(interrupted); afterwards
// the host's own handlers are back and the flag is clear. A signal that arrived and did not
// already end the call with that error is raised again for the host's handlers (Python then
// raises KeyboardInterrupt or terminates, as it would have). Calls in several threads share one scope.
class InterruptScope {
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;

private:
    int exceptions_;
};

// Throws Error(interrupted) once one of the signals has arrived.
void throw_if_interrupted();
bool interrupted();
int interrupting_signal(); // the signal that arrived, or 0

// A path (file or folder) that a second signal must remove before the process dies.
// At most a few are registered at a time; each is removed again with unregister.
void register_staging_path(const std::filesystem::path& path);
void unregister_staging_path(const std::filesystem::path& path);

// Folders made for an output (`innermost` and `levels` - 1 of its parents): removed after the
// staging paths, each only if empty. One such chain at a time.
void register_created_folders(const std::filesystem::path& innermost, int levels);
void unregister_created_folders();

// Removes the registered staging paths (and created folders) now; async-signal-safe (for handlers that end the
// process).
void remove_staging_now();

} // namespace sphkern
