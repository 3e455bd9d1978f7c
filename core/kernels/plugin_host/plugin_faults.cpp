#include "kernels/plugin_host/plugin_faults.hpp"

#include "kernels/plugin_host/plugin_call_guard.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <pthread.h>
#include <unistd.h>

namespace sphkern {

namespace {

constexpr int faults[fault_signal_count] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
constexpr const char* fault_names[fault_signal_count] = {"SIGSEGV", "SIGBUS", "SIGFPE", "SIGILL", "SIGABRT"};
struct sigaction fallback[fault_signal_count]; // where a fault outside a plugin call goes; SIG_DFL at first
pid_t owner = 0;                               // a forked child's exit() is not this process's
bool forked = false;                           // in a child: a crash ends it (the probe reads how)
thread_local sigjmp_buf* recovery = nullptr;   // reached in the handler only once the thread is in a call

int index_of(int sig)
{
    for (int i = 0; i < fault_signal_count; ++i)
        if (faults[i] == sig) return i;
    return 0;
}

extern "C" void on_fault(int sig, siginfo_t* info, void*)
{
    const int i = index_of(sig);
    if (const PluginCall* call = current_plugin_call()) {
        jump_to_recovery_point(sig); // a library host: back to the call, which raises
        char what[64] = "crashed with signal ";
        const char digits[3] = {static_cast<char>('0' + sig / 10), static_cast<char>('0' + sig % 10), 0};
        std::strcat(what, sig >= 10 ? digits : digits + 1);
        std::strcat(what, " (");
        std::strcat(what, fault_names[i]);
        std::strcat(what, ")");
        end_for_plugin(*call, what);
    }
    // Not a plugin's fault: the handler that was there before gets it. A fault of the hardware
    // happens again when the instruction runs again; a sent one (abort, kill) is sent again.
    ::sigaction(sig, &fallback[i], nullptr);
    if (info->si_code <= 0) ::raise(sig);
}

extern "C" void on_exit_call()
{
    if (::getpid() != owner) return;
    if (const PluginCall* call = current_plugin_call()) end_for_plugin(*call, "called exit() or pthread_exit()");
}

} // namespace

void take_fault_signals(struct sigaction* host)
{
    struct sigaction action {};
    action.sa_sigaction = on_fault;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_SIGINFO | SA_ONSTACK; // a stack overflow in a plugin is reported too
    for (int i = 0; i < fault_signal_count; ++i) {
        struct sigaction before {};
        ::sigaction(faults[i], &action, &before);
        if (!host) continue;
        host[i] = before;
        fallback[i] = before;
    }
}

void give_back_fault_signals(const struct sigaction* host)
{
    for (int i = 0; i < fault_signal_count; ++i) ::sigaction(faults[i], &host[i], nullptr);
}

void watch_exit_in_plugin_calls()
{
    static std::once_flag once;
    std::call_once(once, [] {
        owner = ::getpid();
        std::atexit(on_exit_call);
        ::pthread_atfork(nullptr, nullptr, [] { forked = true; });
    });
}

bool plugin_faults_recoverable() { return !process_is_owned() && owner != 0 && !forked; }

void set_recovery_point(sigjmp_buf* point) noexcept { recovery = point; }

void jump_to_recovery_point(int value) noexcept
{
    sigjmp_buf* point = recovery;
    if (!point || !plugin_faults_recoverable()) return;
    recovery = nullptr;
    if (value > 0 && value < NSIG) { // from a fault handler: sigsetjmp saved no mask to unblock it
        sigset_t again;
        sigemptyset(&again);
        sigaddset(&again, value);
        ::sigprocmask(SIG_UNBLOCK, &again, nullptr);
    }
    ::siglongjmp(*point, value);
}

std::string crash_description(int sig)
{
    return "crashed with signal " + std::to_string(sig) + " (" + fault_names[index_of(sig)] + ")";
}

void end_process_with_line(int code, const char* const* parts, int count)
{
    // One line, whichever thread comes first: threads calling the same faulty plugin can
    // fault together, and the others wait here for the process to end.
    static std::atomic<bool> ending{false};
    static_assert(std::atomic<bool>::is_always_lock_free, "used in a signal handler");
    if (ending.exchange(true))
        for (;;) ::pause();
    char line[8192] = "sphkern: error: ";
    std::size_t used = std::strlen(line);
    for (int i = 0; i < count; ++i)
        for (const char* c = parts[i]; *c && used + 1 < sizeof line; ++c) line[used++] = *c;
    line[used++] = '\n';
    for (std::size_t done = 0; done < used;) {
        ssize_t n = ::write(STDERR_FILENO, line + done, used - done);
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
    }
    remove_staging_now();
    ::_exit(code);
}

void end_for_plugin(const PluginCall& call, const char* what)
{
    const char* parts[] = {call.plugin(), " ", what, " in ", call.function(), "; nothing was written"};
    end_process_with_line(static_cast<int>(ExitCode::plugin), parts, 6);
}

} // namespace sphkern
