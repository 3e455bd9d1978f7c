#include "kernels/plugin_file.hpp"

#include "support/error.hpp"
#include "support/process/high_descriptor.hpp"
#include "support/process/resource_errors.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace sphkern {

namespace {

constexpr long long max_plugin_bytes = 256ll << 20;

bool same_content_stamp(const struct stat& a, const struct stat& b)
{
    return a.st_size == b.st_size && a.st_mtim.tv_sec == b.st_mtim.tv_sec && a.st_mtim.tv_nsec == b.st_mtim.tv_nsec &&
           a.st_ctim.tv_sec == b.st_ctim.tv_sec && a.st_ctim.tv_nsec == b.st_ctim.tv_nsec;
}

} // namespace

PluginFile::PluginFile(const std::filesystem::path& file) : name_(file.string())
{
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0)
        throw Error(ExitCode::plugin, name_ + ": no such plugin file", ErrorKind::missing_file);
    if (S_ISDIR(st.st_mode)) throw Error(ExitCode::plugin, name_ + ": is a folder, expected a plugin file");
    // A device or a pipe would be read without end by the loader (and opening a FIFO would block).
    if (!S_ISREG(st.st_mode))
        throw Error(ExitCode::plugin, name_ + ": is not a regular file (a device or pipe?), expected a shared library");
    // Out of reach of a constructor that closes the low descriptors: the load reads through it.
    fd_ = move_out_of_reach(::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
    if (fd_ < 0) {
        if (is_resource_error(errno)) fail_resource(errno, name_ + ": cannot be opened");
        throw Error(ExitCode::plugin, name_ + ": cannot be opened: " + std::strerror(errno));
    }
    if (::fstat(fd_, &status_) != 0 || !S_ISREG(status_.st_mode)) {
        ::close(fd_);
        throw Error(ExitCode::plugin, name_ + ": is not a regular file (it was replaced while it was opened)");
    }
    if (status_.st_size > max_plugin_bytes) {
        ::close(fd_);
        throw Error(ExitCode::plugin, name_ + ": file is " + std::to_string(status_.st_size) +
                                          " bytes, more than the limit of " + std::to_string(max_plugin_bytes) +
                                          " for a plugin");
    }
    loader_ = "/proc/self/fd/" + std::to_string(fd_);
}

PluginFile::~PluginFile()
{
    if (!kept_ && fd_ >= 0) ::close(fd_);
}

bool PluginFile::unchanged() const
{
    struct stat now {};
    return ::fstat(fd_, &now) == 0 && same_content_stamp(now, status_);
}

} // namespace sphkern
