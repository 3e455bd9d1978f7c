#include "support/process/child_process.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sphkern {

namespace {

void kill_and_reap(pid_t pid)
{
    ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
}

// The child's side: its own process group, stdin from /dev/null, stdout and stderr into
// the pipe, then the program. Only async-signal-safe calls between fork and exec.
[[noreturn]] void exec_in_child(char* const* args, int write_fd, const char* folder)
{
    ::setpgid(0, 0); // its own process group: the terminal's Ctrl-C reaches sphkern, which stops it
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) ::signal(sig, SIG_DFL);
    int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (null >= 0) ::dup2(null, STDIN_FILENO);
    ::dup2(write_fd, STDOUT_FILENO);
    ::dup2(write_fd, STDERR_FILENO);
    if (::chdir(folder) != 0) ::_exit(126);
    ::execv(args[0], args);
    ::_exit(127);
}

using Deadline = decltype(std::chrono::steady_clock::now() + std::chrono::duration<double>());

// The first 64 KiB of the child's output, until it closes the pipe; false when the
// deadline passed first. An interruption kills the child and throws.
bool read_output(int read_fd, pid_t pid, Deadline deadline, std::string& output)
{
    char buffer[4096];
    for (;;) {
        if (interrupted()) {
            ::close(read_fd);
            kill_and_reap(pid);
            throw_if_interrupted();
        }
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        pollfd p{read_fd, POLLIN, 0};
        // Wake at least every 200 ms to look at the interrupt flag.
        int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 200)));
        if (ready <= 0) continue; // timeout slice or EINTR
        ssize_t n = ::read(read_fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return true;
        if (output.size() < (64u << 10)) output.append(buffer, static_cast<std::size_t>(n));
    }
}

// The child's exit after its output closed, still bounded in time and interruptible;
// false (the child killed) when the deadline passed first.
bool wait_for_exit(pid_t pid, Deadline deadline, int& status)
{
    for (;;) {
        pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid || (done < 0 && errno != EINTR)) return true;
        if (interrupted()) {
            kill_and_reap(pid);
            throw_if_interrupted();
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            kill_and_reap(pid);
            return false;
        }
        ::usleep(10000);
    }
}

} // namespace

ProgramResult run_program(const std::vector<std::string>& argv, const std::filesystem::path& folder,
                          double timeout_seconds)
{
    throw_if_interrupted();
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const std::string where = folder.string();

    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw Error(ExitCode::output, "cannot start " + argv.at(0) + ": " + std::strerror(errno));
    pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw Error(ExitCode::output, "cannot start " + argv.at(0) + ": " + std::strerror(errno));
    }
    if (pid == 0) exec_in_child(args.data(), fds[1], where.c_str());
    ::close(fds[1]);
    spdlog::debug("started {} (pid {}) in {}", argv[0], pid, where);
    ProgramResult result;
    const Deadline deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
    const bool closed = read_output(fds[0], pid, deadline, result.output);
    ::close(fds[0]);
    int status = 0;
    if (!closed) kill_and_reap(pid);
    if (!closed || !wait_for_exit(pid, deadline, status)) {
        result.timed_out = true;
        return result;
    }
    throw_if_interrupted();
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    else result.exit_status = WEXITSTATUS(status);
    if (result.exit_status == 126) result.output = "cannot enter the folder " + where;
    if (result.exit_status == 127) result.output = "cannot execute " + argv[0];
    return result;
}

} // namespace sphkern
