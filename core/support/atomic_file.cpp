#include "support/atomic_file.hpp"

#include "support/error.hpp"

#include <fstream>
#include <unistd.h>

namespace sphkern {
namespace fs = std::filesystem;

void write_file_atomically(const fs::path& file, const std::function<void(std::ostream&)>& write)
{
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw Error(ExitCode::output, file.string() + ": is a folder, expected a file name");
    fs::path partial = file.string() + ".partial-" + std::to_string(::getpid());
    {
        std::ofstream out(partial, std::ios::binary);
        if (!out) throw Error(ExitCode::output, file.string() + ": cannot be written");
        write(out);
        out.close();
        if (!out) {
            fs::remove(partial, ec);
            throw Error(ExitCode::output, file.string() + ": writing failed (disk full?)");
        }
    }
    fs::rename(partial, file, ec);
    if (ec) {
        fs::remove(partial, ec);
        throw Error(ExitCode::output, file.string() + ": cannot be moved into place");
    }
}

} // namespace sphkern
