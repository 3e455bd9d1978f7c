#include "support/process/resource_errors.hpp"

#include <cerrno>
#include <cstring>
#include <sys/resource.h>

namespace sphkern {

bool is_resource_error(int error) { return error == EMFILE || error == ENFILE || error == EAGAIN || error == ENOMEM; }

void fail_resource(int error, const std::string& doing)
{
    struct rlimit limit {};
    if (error == EMFILE || error == ENFILE) {
        const bool known = error == EMFILE && ::getrlimit(RLIMIT_NOFILE, &limit) == 0;
        throw ResourceError(doing + ": too many open files" +
                            (known ? " (the limit is " + std::to_string(limit.rlim_cur) + ", ulimit -n)"
                                   : std::string(" in the system")) +
                            "; raise the limit");
    }
    if (error == EAGAIN && ::getrlimit(RLIMIT_NPROC, &limit) == 0)
        throw ResourceError(doing + ": cannot start another process (the limit is " + std::to_string(limit.rlim_cur) +
                            ", ulimit -u); raise the limit");
    throw ResourceError(doing + ": " + std::strerror(error) + " (a limit of the system)");
}

} // namespace sphkern
