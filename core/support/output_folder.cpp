#include "support/output_folder.hpp"

#include "support/error.hpp"
#include "support/interruption.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace sphkern {
namespace fs = std::filesystem;

OutputFolder::OutputFolder(fs::path target, bool overwrite) : target_(std::move(target)), overwrite_(overwrite)
{
    std::error_code ec;
    if (target_.filename().empty()) target_ = target_.parent_path();
    if (fs::exists(target_, ec) && !overwrite_)
        throw Error(ExitCode::output, target_.string() + ": already exists; use --force to replace it");
    if (fs::exists(target_, ec) && !fs::is_directory(target_, ec))
        throw Error(ExitCode::output, target_.string() + ": exists and is not a folder");
    fs::path parent = fs::absolute(target_).parent_path();
    fs::create_directories(parent, ec);
    if (ec) throw Error(ExitCode::output, parent.string() + ": cannot create the folder: " + ec.message());
    std::string pattern = (parent / ("." + target_.filename().string() + ".partial-XXXXXX")).string();
    if (!::mkdtemp(pattern.data()))
        throw Error(ExitCode::output, parent.string() + ": cannot create a folder there: " + std::strerror(errno));
    staging_ = pattern;
    // mkdtemp makes it private; results are ordinary files (the umask still applies to them).
    fs::permissions(staging_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                  fs::perms::others_read | fs::perms::others_exec, ec);
}

OutputFolder::~OutputFolder()
{
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

void OutputFolder::write(const std::string& name, const std::string& content)
{
    fs::path file = staging_ / name;
    std::ofstream out(file, std::ios::binary);
    out << content;
    out.close();
    if (!out) throw Error(ExitCode::output, file.string() + ": cannot write (disk full?)");
}

void OutputFolder::commit()
{
    throw_if_interrupted();
    std::error_code ec;
    fs::path old;
    if (fs::exists(target_, ec)) {
        old = staging_.string() + ".old";
        fs::rename(target_, old, ec);
        if (ec) throw Error(ExitCode::output, target_.string() + ": cannot replace: " + ec.message());
    }
    fs::rename(staging_, target_, ec);
    if (ec) {
        if (!old.empty()) fs::rename(old, target_, ec);
        throw Error(ExitCode::output, target_.string() + ": cannot move the results into place: " + ec.message());
    }
    committed_ = true;
    if (!old.empty()) fs::remove_all(old, ec);
}

} // namespace sphkern
