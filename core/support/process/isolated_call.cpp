#include "support/process/isolated_call.hpp"

#include "support/process/resource_errors.hpp"

#include "support/process/high_descriptor.hpp"
#include "support/process/interruption.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <exception>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sphkern {

namespace {

void write_all(int fd, const std::string& data)
{
    const char* p = data.data();
    std::size_t left = data.size();
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        p += n;
        left -= static_cast<std::size_t>(n);
    }
}

// The child's side: the work's answer, or its exception, prefixed 'o' or 'e', down the pipe.
[[noreturn]] void answer_in_child(int write_fd, const std::function<std::string()>& work)
{
    ::setpgid(0, 0); // the terminal's Ctrl-C goes to sphkern, which stops the child
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::signal(sig, SIG_DFL);
    // The plugin's faults must kill this child, whatever handlers the parent installed.
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP}) ::signal(sig, SIG_DFL);
    std::string out;
    char status = 'o';
    try {
        out = work();
    } catch (const std::exception& e) {
        status = 'e';
        out = e.what();
    } catch (...) {
        status = 'e';
        out = "threw an unknown C++ exception";
    }
    write_all(write_fd, std::string(1, status) + out);
    ::close(write_fd);
    ::_exit(0); // no atexit handlers or static destructors of the parent's state
}

void wait_for(pid_t pid, int* status)
{
    while (::waitpid(pid, status, 0) < 0 && errno == EINTR) {}
}

struct ChildAnswer {
    std::string received;
    bool timed_out = false;
};

// Everything the child writes until it closes the pipe or the deadline passes. An
// interruption kills the child (it may ignore SIGINT) and throws.
ChildAnswer read_answer(int read_fd, pid_t pid, double timeout_seconds)
{
    ChildAnswer answer;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
    char buffer[65536];
    for (;;) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            answer.timed_out = true;
            return answer;
        }
        if (interrupted()) {
            ::close(read_fd);
            ::kill(pid, SIGKILL);
            wait_for(pid, nullptr);
            throw_if_interrupted();
        }
        pollfd p{read_fd, POLLIN, 0};
        int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 200)));
        if (ready <= 0) continue; // EINTR, or a slice of the wait: look at the flag and the deadline again
        ssize_t n = ::read(read_fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return answer;
        answer.received.append(buffer, static_cast<std::size_t>(n));
    }
}

// The work's answer, or why there is none, from what the child wrote and how it ended.
std::variant<std::string, IsolatedFailure> outcome(const ChildAnswer& answer, int status, double timeout_seconds)
{
    if (answer.timed_out) {
        char text[64];
        std::snprintf(text, sizeof text, "did not finish within %g s (endless loop?)", timeout_seconds);
        return IsolatedFailure{text};
    }
    if (WIFSIGNALED(status)) {
        int sig = WTERMSIG(status);
        return IsolatedFailure{"crashed with signal " + std::to_string(sig) + " (" + ::strsignal(sig) + ")"};
    }
    const std::string& received = answer.received;
    if (received.empty())
        return IsolatedFailure{"exited with status " + std::to_string(WEXITSTATUS(status)) + " before answering"};
    if (received[0] == 'e') return IsolatedFailure{"threw an exception: " + received.substr(1)};
    return received.substr(1);
}

} // namespace

std::variant<std::string, IsolatedFailure> run_isolated(const std::function<std::string()>& work,
                                                        double timeout_seconds)
{
    int fds[2];
    // A limit of the machine is no fault of the work: named as what it is.
    if (::pipe(fds) != 0) {
        if (is_resource_error(errno)) fail_resource(errno, "cannot create a pipe for a child process");
        return IsolatedFailure{std::string("cannot create a pipe: ") + std::strerror(errno)};
    }
    pid_t pid = ::fork();
    if (pid < 0) {
        const int error = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        if (is_resource_error(error)) fail_resource(error, "cannot start a child process");
        return IsolatedFailure{std::string("cannot fork: ") + std::strerror(error)};
    }
    if (pid == 0) {
        ::close(fds[0]);
        answer_in_child(move_out_of_reach(fds[1]), work);
    }
    ::close(fds[1]);
    const ChildAnswer answer = read_answer(fds[0], pid, timeout_seconds);
    ::close(fds[0]);
    if (answer.timed_out) ::kill(pid, SIGKILL);
    // What the work left in the child's process group (a plugin's forked children) ends with
    // it: the group is killed while the child, exited but not reaped, still holds its id.
    siginfo_t exited{};
    while (::waitid(P_PID, static_cast<id_t>(pid), &exited, WEXITED | WNOWAIT) != 0 && errno == EINTR) {}
    ::kill(-pid, SIGKILL);
    int status = 0;
    wait_for(pid, &status);
    return outcome(answer, status, timeout_seconds);
}

} // namespace sphkern
