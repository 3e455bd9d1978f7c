#include "support/process/stray_children.hpp"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sphkern {

namespace {

// The pids of this process's children: every thread's /proc list where the kernel keeps one
// (CONFIG_PROC_CHILDREN), else the processes whose parent (field 4 of /proc/PID/stat) is this one.
std::vector<pid_t> children()
{
    std::vector<pid_t> pids;
    std::error_code ec;
    bool listed = false;
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
        std::ifstream list(task.path() / "children");
        listed = listed || list.is_open();
        for (pid_t pid; list >> pid;) pids.push_back(pid);
    }
    if (listed) return pids;
    const pid_t self = ::getpid();
    for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        if (!std::getline(stat, line)) continue;
        // pid (comm) state ppid ...: comm may hold spaces and parentheses, so read after the last ')'.
        const auto close = line.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(line.substr(close + 1));
        char state = 0;
        long parent = 0;
        if (rest >> state >> parent && parent == self) pids.push_back(static_cast<pid_t>(std::stol(line)));
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
