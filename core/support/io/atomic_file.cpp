#include "support/io/atomic_file.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace sphkern {
namespace fs = std::filesystem;

void write_file_atomically(const fs::path& file, const std::function<void(std::ostream&)>& write)
{
    std::error_code ec;
    const fs::path target = fs::absolute(file, ec).lexically_normal();
    const std::string name = file.string();
    struct stat st {};
    if (::lstat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw Error(ExitCode::output,
                    name + ": " +
                        (S_ISDIR(st.st_mode)
                             ? "is a folder, expected a file name"
                             : "is not a regular file (a link, device or pipe); refusing to replace it"));
    if (target.filename().empty()) throw Error(ExitCode::output, name + ": expected a file name");
    std::string name_pattern = ".";
    name_pattern += target.filename().string();
    name_pattern += ".partial-XXXXXX";
    std::string pattern = (target.parent_path() / name_pattern).string();
    int fd = ::mkstemp(pattern.data());
    if (fd < 0) throw Error(ExitCode::output, name + ": cannot be written: " + std::strerror(errno));
    const fs::path partial = pattern;
    register_staging_path(partial);
    auto discard = [&] {
        ::unlink(partial.c_str());
        unregister_staging_path(partial);
    };
    // mkstemp makes it private; a new file gets the umask's permissions, a replaced one keeps its own.
    mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, ::lstat(target.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~mask));
    ::close(fd);
    try {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        if (!out) throw Error(ExitCode::output, name + ": cannot be written");
        write(out);
        out.close();
        if (!out) throw Error(ExitCode::output, name + ": writing failed (disk full?)");
        throw_if_interrupted();
    } catch (...) {
        discard();
        throw;
    }
    // Looked at again just before: a link or device put there meanwhile is not replaced.
    if (::lstat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        discard();
        throw Error(ExitCode::output,
                    name + ": is not a regular file (a link, device or pipe); refusing to replace it");
    }
    if (std::rename(partial.c_str(), target.c_str()) != 0) {
        int error = errno;
        discard();
        throw Error(ExitCode::output, name + ": cannot be moved into place: " + std::strerror(error));
    }
    unregister_staging_path(partial);
}

} // namespace sphkern
