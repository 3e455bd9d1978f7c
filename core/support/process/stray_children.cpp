#include "support/process/stray_children.hpp"

#include <sys/prctl.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <vector>

namespace sphkern {

namespace {

// The pids of this process's children (every thread's, from /proc: Linux 3.5 and later).
std::vector<pid_t> children()
{
    std::vector<pid_t> pids;
    std::error_code ec;
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
        std::ifstream list(task.path() / "children");
        for (pid_t pid; list >> pid;) pids.push_back(pid);
    }
    return pids;
}

} // namespace

void adopt_orphans() { ::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0); }

void end_stray_children()
{
    for (int round = 0; round < 8; ++round) {
        const auto pids = children();
        if (pids.empty()) return;
        for (pid_t pid : pids) ::kill(pid, SIGKILL);
        for (pid_t pid : pids) ::waitpid(pid, nullptr, 0);
    }
}

} // namespace sphkern
