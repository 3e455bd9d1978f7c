// Progress of long work on stderr. On a terminal one line rewritten in place; otherwise
// (a log file, a pipe) a plain log line every 5 s once the work has taken 2 s, with what
// is done and an estimate of the rest. SPHKERN_PROGRESS_SECONDS sets both times (0: a
// line at every step).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace sphkern {

class Progress {
public:
    // `scope` follows the estimate: what its "left" covers (" in this part ...").
    Progress(std::string what, std::size_t total, std::string scope = "");
    ~Progress();
    void step(const std::string& item) { reach(done_ + 1, item); }
    // `done` of the total finished (work shared out among threads, told by one of them).
    void reach(std::size_t done, const std::string& item);

private:
    using Clock = std::chrono::steady_clock;
    std::string what_, scope_;
    std::size_t total_, done_ = 0;
    bool terminal_;
    double first_after_ = 2, every_ = 5; // seconds
    Clock::time_point start_, last_line_;
};

} // namespace sphkern
