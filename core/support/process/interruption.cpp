#include "support/process/interruption.hpp"

#include "support/error.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <exception>
#include <fcntl.h>
#include <mutex>
#include <sys/syscall.h>
#include <unistd.h>

namespace sphkern {

namespace {

std::atomic<int> received{0};

// Registered staging paths, fixed-size so that the handler needs no allocation.
constexpr int slots = 8;
constexpr std::size_t path_bytes = 4096;
char staged[slots][path_bytes];
std::atomic<bool> used[slots];

// The folders a run created for its output (the innermost, and how many levels up), removed
// after the staging paths if they are empty.
char created[path_bytes];
std::atomic<int> created_levels{0};

struct linux_dirent64 {
    ino64_t d_ino;
    off64_t d_off;
    unsigned short d_reclen;
    unsigned char d_type;
    char d_name[];
};

// Removes the contents of the directory `dir` (an open descriptor), depth-first,
// with openat, getdents64 and unlinkat only: all async-signal-safe.
void remove_contents(int dir, int depth)
{
    if (depth > 16) return;
    alignas(8) char buffer[4096];
    for (;;) {
        long n = ::syscall(SYS_getdents64, dir, buffer, sizeof buffer);
        if (n <= 0) return;
        bool removed_any = false;
        for (long at = 0; at < n;) {
            auto* entry = reinterpret_cast<linux_dirent64*>(buffer + at);
            at += entry->d_reclen;
            const char* name = entry->d_name;
            if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
            if (::unlinkat(dir, name, 0) == 0) {
                removed_any = true;
                continue;
            }
            int sub = ::openat(dir, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (sub < 0) continue;
            remove_contents(sub, depth + 1);
            ::close(sub);
            if (::unlinkat(dir, name, AT_REMOVEDIR) == 0) removed_any = true;
        }
        if (removed_any) ::lseek(dir, 0, SEEK_SET); // entries moved: read the folder again
    }
}

} // namespace

void remove_staging_now()
{
    for (int i = 0; i < slots; ++i) {
        if (!used[i].load()) continue;
        if (::unlink(staged[i]) == 0) continue;
        int dir = ::open(staged[i], O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (dir < 0) continue;
        remove_contents(dir, 0);
        ::close(dir);
        ::rmdir(staged[i]);
    }
    char folder[path_bytes];
    const int levels = created_levels.load();
    if (levels <= 0) return;
    std::memcpy(folder, created, path_bytes);
    for (int i = 0; i < levels; ++i) {
        if (::rmdir(folder) != 0) return; // not empty (not only ours), or gone
        char* slash = std::strrchr(folder, '/');
        if (!slash || slash == folder) return;
        *slash = '\0';
    }
}

namespace {

// The command line owns its process: a second signal ends it. A library host keeps its process.
std::atomic<bool> owns_process{false};

extern "C" void on_signal(int sig)
{
    if (received.exchange(sig) != 0 && owns_process.load()) { // a second signal: clean up and stop at once
        remove_staging_now();
        struct sigaction plain {};
        plain.sa_handler = SIG_DFL;
        ::sigaction(sig, &plain, nullptr);
        ::raise(sig);
    }
}

constexpr int handled[] = {SIGINT, SIGTERM, SIGHUP};

SignalHook hook; // constant-initialised: empty until a plugin is first loaded

void take_signals(struct sigaction* saved, struct sigaction* saved_hooked)
{
    if (hook.take) hook.take(saved_hooked);
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0; // no SA_RESTART: a blocking wait returns EINTR and checks the flag
    for (int i = 0; i < 3; ++i) ::sigaction(handled[i], &action, saved ? &saved[i] : nullptr);
}

// The library host's scopes: how many calls are inside one, and the host's handlers to give back.
std::mutex scope_mutex;
int scopes = 0;
struct sigaction host_handlers[3];
struct sigaction host_hooked[max_hooked_signals];

} // namespace

void set_signal_hook(SignalHook h)
{
    std::lock_guard lock(scope_mutex);
    if (hook.take) return;
    hook = h;
    if (owns_process.load()) hook.take(nullptr);
    else if (scopes > 0) hook.take(host_hooked);
}

bool process_is_owned() { return owns_process.load(); }

void install_interrupt_handlers()
{
    owns_process = true;
    take_signals(nullptr, nullptr);
}

void restore_interrupt_handlers()
{
    std::lock_guard lock(scope_mutex);
    if (owns_process.load() || scopes > 0) take_signals(nullptr, nullptr);
}

InterruptScope::InterruptScope() : exceptions_(std::uncaught_exceptions())
{
    std::lock_guard lock(scope_mutex);
    if (scopes++ > 0 || owns_process.load()) return;
    received = 0;
    take_signals(host_handlers, host_hooked);
}

InterruptScope::~InterruptScope()
{
    std::lock_guard lock(scope_mutex);
    if (--scopes > 0 || owns_process.load()) return;
    for (int i = 0; i < 3; ++i) ::sigaction(handled[i], &host_handlers[i], nullptr);
    if (hook.give_back) hook.give_back(host_hooked);
    const int sig = received.exchange(0);
    // SIGINT that ended the call is already the call's error; any other arrival goes to the host.
    const bool reported = sig == SIGINT && std::uncaught_exceptions() > exceptions_;
    if (sig != 0 && !reported) ::raise(sig);
}

bool interrupted() { return received.load() != 0; }

int interrupting_signal() { return received.load(); }

void throw_if_interrupted()
{
    int sig = received.load();
    if (sig == 0) return;
    const char* name = sig == SIGINT    ? "interrupted (SIGINT)"
                       : sig == SIGTERM ? "terminated (SIGTERM)"
                                        : "hung up (SIGHUP)";
    throw Error(ExitCode::interrupted, std::string(name) + ": nothing was written");
}

void register_staging_path(const std::filesystem::path& path)
{
    const std::string text = std::filesystem::absolute(path).string();
    if (text.size() >= path_bytes) return;
    for (int i = 0; i < slots; ++i) {
        if (used[i].load()) continue;
        std::memcpy(staged[i], text.c_str(), text.size() + 1);
        used[i].store(true);
        return;
    }
}

void unregister_staging_path(const std::filesystem::path& path)
{
    const std::string text = std::filesystem::absolute(path).string();
    for (int i = 0; i < slots; ++i)
        if (used[i].load() && text == staged[i]) used[i].store(false);
}

void register_created_folders(const std::filesystem::path& innermost, int levels)
{
    const std::string text = std::filesystem::absolute(innermost).string();
    if (text.size() >= path_bytes || created_levels.load() != 0) return;
    std::memcpy(created, text.c_str(), text.size() + 1);
    created_levels.store(levels);
}

void unregister_created_folders() { created_levels.store(0); }

} // namespace sphkern
