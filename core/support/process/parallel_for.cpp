#include "support/process/parallel_for.hpp"

#include <spdlog/spdlog.h>

namespace sphkern {

void warn_fewer_threads(int threads, const std::string& reason)
{
    static std::atomic<bool> said{false};
    if (!said.exchange(true))
        spdlog::warn("cannot start {} threads ({}); the work runs on the threads the system allows", threads, reason);
}

} // namespace sphkern
