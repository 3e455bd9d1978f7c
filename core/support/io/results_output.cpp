#include "support/io/results_output.hpp"

#include "support/error.hpp"
#include "support/process/high_descriptor.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sphkern {

namespace {

std::FILE* results = nullptr;
struct stat original {};

} // namespace

void separate_results_from_stdout()
{
    if (results) return;
    // High, out of reach of a plugin's constructor that closes the low descriptors.
    int fd = move_out_of_reach(::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3));
    if (fd < 0) return; // stdout is closed: results go nowhere, as they would have
    results = ::fdopen(fd, "w");
    if (!results) {
        ::close(fd);
        return;
    }
    ::fstat(fd, &original);
    std::fflush(stdout);
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
}

std::FILE* results_file() { return results ? results : stdout; }

void check_results_output()
{
    if (!results) return;
    struct stat now {};
    if (::fstat(::fileno(results), &now) != 0 || now.st_dev != original.st_dev || now.st_ino != original.st_ino)
        throw Error(ExitCode::plugin, "a plugin closed or replaced sphkern's output descriptor while loading");
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
}

} // namespace sphkern
