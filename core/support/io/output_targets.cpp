#include "support/io/output_targets.hpp"

#include "support/error.hpp"

#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace sphkern {
namespace fs = std::filesystem;

namespace {

// One file: the same path, or two names of one existing file (a link, "./x" and "x").
bool same_file(const std::string& a, const std::string& b)
{
    std::error_code ec;
    if (fs::absolute(a, ec).lexically_normal() == fs::absolute(b, ec).lexically_normal()) return true;
    return fs::equivalent(a, b, ec);
}

} // namespace

void check_output_targets(const std::vector<OutputTarget>& outputs, const std::vector<std::string>& inputs)
{
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [option, path] = outputs[i];
        if (path.empty()) throw Error(ExitCode::usage, option + " needs a file name");
        for (const auto& input : inputs)
            if (!input.empty() && same_file(path, input))
                throw Error(ExitCode::output,
                            option + " " + path + ": is a file this run reads; choose another output file");
        for (std::size_t j = 0; j < i; ++j)
            if (same_file(path, outputs[j].path))
                throw Error(ExitCode::output, option + " " + path + ": " + outputs[j].option +
                                                  " names the same file; give each output its own file");
        struct stat st {};
        if (::lstat(path.c_str(), &st) != 0) continue; // a new file
        if (S_ISDIR(st.st_mode))
            throw Error(ExitCode::output, option + " " + path + ": is a folder, expected a file name");
        if (!S_ISREG(st.st_mode))
            throw Error(ExitCode::output,
                        option + " " + path +
                            ": is not a regular file (a link, device or pipe); refusing to replace it");
        if (::access(path.c_str(), W_OK) != 0)
            throw Error(ExitCode::output, option + " " + path + ": is read-only for this user; refusing to replace it");
    }
}

} // namespace sphkern
