#include "support/process/progress.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace sphkern {

namespace {

// "about 12 s left" from the mean time per step so far.
std::string estimate(double elapsed, std::size_t done, std::size_t total, const std::string& scope)
{
    if (done == 0 || done >= total) return "";
    const double left = elapsed / double(done) * double(total - done);
    return (left < 90 ? fmt::format(", about {:.0f} s left", std::ceil(left))
                      : fmt::format(", about {:.0f} min left", std::ceil(left / 60))) +
           scope;
}

} // namespace

Progress::Progress(std::string what, std::size_t total, std::string scope)
    : what_(std::move(what)), scope_(std::move(scope)), total_(total), terminal_(::isatty(STDERR_FILENO) == 1),
      start_(Clock::now()), last_line_(start_)
{
    if (const char* seconds = std::getenv("SPHKERN_PROGRESS_SECONDS")) {
        char* end = nullptr;
        const double value = std::strtod(seconds, &end);
        if (end != seconds && *end == '\0' && std::isfinite(value) && value >= 0) first_after_ = every_ = value;
    }
}

Progress::~Progress()
{
    if (terminal_ && done_ > 0) std::fprintf(stderr, "\r\033[K");
}

void Progress::reach(std::size_t done, const std::string& item)
{
    done_ = done;
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (terminal_) {
        std::fprintf(stderr, "\r\033[K%s: %zu/%zu %s%s", what_.c_str(), done_, total_, item.c_str(),
                     estimate(elapsed, done_, total_, scope_).c_str());
        return;
    }
    if (elapsed < first_after_ || std::chrono::duration<double>(now - last_line_).count() < every_) return;
    last_line_ = now;
    spdlog::info("{}: {}/{} done (last: {}), {:.0f} s so far{}", what_, done_, total_, item, elapsed,
                 estimate(elapsed, done_, total_, scope_));
}

} // namespace sphkern
