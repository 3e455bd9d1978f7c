// Starts another program without a shell: an argument vector, a working folder and a
// time bound. The child's output is collected; an interrupt of sphkern stops it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

struct ProgramResult {
    int exit_status = -1; // -1 when killed by a signal
    int signal = 0;
    bool timed_out = false;
    std::string output; // stdout and stderr together, at most the first 64 KiB
};

// Runs `argv[0]` (a path, not searched on PATH) with `argv` in `folder`. Throws
// Error(interrupted) if SIGINT, SIGTERM or SIGHUP arrives meanwhile (the child is killed
// first), Error(output) if the program cannot be started.
ProgramResult run_program(const std::vector<std::string>& argv, const std::filesystem::path& folder,
                          double timeout_seconds);

} // namespace sphkern
