#include "support/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace sphkern {

Progress::Progress(std::string what, std::size_t total)
    : what_(std::move(what)), total_(total), enabled_(::isatty(STDERR_FILENO) == 1)
{
}

Progress::~Progress()
{
    if (enabled_ && done_ > 0) std::fprintf(stderr, "\r\033[K");
}

void Progress::step(const std::string& item)
{
    ++done_;
    if (enabled_) std::fprintf(stderr, "\r\033[K%s: %zu/%zu %s", what_.c_str(), done_, total_, item.c_str());
}

} // namespace sphkern
