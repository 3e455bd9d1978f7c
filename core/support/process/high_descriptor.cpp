#include "support/process/high_descriptor.hpp"

#include <algorithm>
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

namespace sphkern {

int move_out_of_reach(int fd)
{
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) limit.rlim_cur = 1024;
    const int floor = static_cast<int>(std::min<rlim_t>(limit.rlim_cur, 65536) / 2);
    if (fd < 0 || floor <= fd) return fd;
    const int high = ::fcntl(fd, F_DUPFD_CLOEXEC, floor);
    if (high < 0) return fd;
    ::close(fd);
    return high;
}

} // namespace sphkern
