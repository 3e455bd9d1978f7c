#include "support/child_process.hpp"

#include "support/error.hpp"
#include "support/interruption.hpp"

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
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
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
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec.
        ::setpgid(0, 0); // its own process group: the terminal's Ctrl-C reaches sphkern, which stops it
        for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) ::signal(sig, SIG_DFL);
        int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
        if (null >= 0) ::dup2(null, STDIN_FILENO);
        ::dup2(fds[1], STDOUT_FILENO);
        ::dup2(fds[1], STDERR_FILENO);
        if (::chdir(where.c_str()) != 0) ::_exit(126);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    ::close(fds[1]);
    spdlog::debug("started {} (pid {}) in {}", argv[0], pid, where);
    ProgramResult result;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
    char buffer[4096];
    for (;;) {
        if (interrupted()) {
            ::close(fds[0]);
            kill_and_reap(pid);
            throw_if_interrupted();
        }
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            result.timed_out = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        // Wake at least every 200 ms to look at the interrupt flag.
        int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 200)));
        if (ready <= 0) continue; // timeout slice or EINTR
        ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        if (result.output.size() < (64u << 10)) result.output.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fds[0]);
    if (result.timed_out) {
        kill_and_reap(pid);
        return result;
    }
    int status = 0;
    for (;;) { // output closed: wait for the exit, still bounded in time and interruptible
        pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid || (done < 0 && errno != EINTR)) break;
        if (interrupted()) {
            kill_and_reap(pid);
            throw_if_interrupted();
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            kill_and_reap(pid);
            result.timed_out = true;
            return result;
        }
        ::usleep(10000);
    }
    throw_if_interrupted();
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    else result.exit_status = WEXITSTATUS(status);
    if (result.exit_status == 126) result.output = "cannot enter the folder " + where;
    if (result.exit_status == 127) result.output = "cannot execute " + argv[0];
    return result;
}

} // namespace sphkern
