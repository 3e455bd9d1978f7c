#include "support/io/output_folder.hpp"
#include "support/text/setting_names.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <spdlog/spdlog.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace sphkern {
namespace fs = std::filesystem;

namespace {

bool lexists(const fs::path& path)
{
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0;
}

// renameat2 with a flag; if the file system cannot do it, says so with ENOSYS/EINVAL in errno.
int rename_with(const fs::path& from, const fs::path& to, unsigned flags)
{
    return ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), flags);
}

// ".<name>.partial-<pid>-XXXXXX": the pid lets a later run recognise a dead run's leftovers.
std::string staging_prefix(const fs::path& target)
{
    std::string prefix = ".";
    prefix += target.filename().string();
    prefix += ".partial-";
    return prefix;
}

// Removes staging folders of runs that died without cleaning up (SIGKILL, power loss):
// only ours (marker inside, our naming), and only if their process is gone.
void remove_stale_staging(const fs::path& target)
{
    std::error_code ec;
    const std::string prefix = staging_prefix(target);
    for (const auto& entry : fs::directory_iterator(target.parent_path(), ec)) {
        std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0) continue;
        long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
        if (pid <= 0 || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        if (!written_by_sphkern(entry.path())) continue;
        fs::remove_all(entry.path(), ec);
    }
}

} // namespace

bool written_by_sphkern(const fs::path& folder)
{
    struct stat st {};
    if (::lstat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return false;
    return ::lstat((folder / OutputFolder::marker_name).c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

OutputFolder::OutputFolder(const fs::path& target, bool overwrite) : overwrite_(overwrite)
{
    std::error_code ec;
    target_ = fs::absolute(target, ec).lexically_normal();
    if (target_.filename().empty()) target_ = target_.parent_path();
    if (ec || target_.filename().empty() || target_.filename() == "..")
        throw Error(ExitCode::output, target.string() + ": not a usable name for a results folder");
    if (lexists(target_)) {
        if (!overwrite_)
            throw Error(ExitCode::output,
                        target_.string() + ": already exists; use " + setting_named("force") + " to replace it");
        if (!written_by_sphkern(target_))
            throw Error(ExitCode::output, target_.string() + ": exists and is not a results folder sphkern wrote (no " +
                                              marker_name + " inside); refusing to replace it");
    }
    make_parents();
    remove_stale_staging(target_);
    std::string pattern =
        (target_.parent_path() / (staging_prefix(target_) + std::to_string(::getpid()) + "-XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) {
        int error = errno;
        remove_created_parents();
        throw Error(ExitCode::output,
                    target_.parent_path().string() + ": cannot create a folder there: " + std::strerror(error));
    }
    staging_ = pattern;
    register_staging_path(staging_);
    spdlog::debug("staging results in {}", staging_.string());
    // mkdtemp makes it private; results are ordinary files (the umask still applies to them).
    fs::permissions(staging_,
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                        fs::perms::others_exec,
                    ec);
    try {
        write(marker_name, "This folder was written by sphkern, which may replace it when told to.\n");
    } catch (...) { // the destructor does not run for a constructor that throws
        unregister_staging_path(staging_);
        fs::remove_all(staging_, ec);
        remove_created_parents();
        throw;
    }
}

// Makes the missing parents one by one, remembering them so that a failed run removes them
// (a path too long for the system fails part of the way: what was made is removed then).
void OutputFolder::make_parents()
{
    std::vector<fs::path> missing;
    for (fs::path p = target_.parent_path(); !p.empty() && !lexists(p); p = p.parent_path()) {
        missing.insert(missing.begin(), p);
        if (p == p.parent_path()) break;
    }
    for (const auto& p : missing) {
        if (::mkdir(p.c_str(), 0777) != 0) {
            if (errno == EEXIST) continue; // made by someone else meanwhile: not ours to remove
            const int error = errno;
            remove_created_parents();
            throw Error(ExitCode::output, p.string() + ": cannot create the folder: " + std::strerror(error));
        }
        created_parents_.push_back(p);
    }
    // A run that dies at a signal or a plugin's crash removes them too, from the handler.
    if (!created_parents_.empty())
        register_created_folders(created_parents_.back(), static_cast<int>(created_parents_.size()));
}

void OutputFolder::remove_created_parents()
{
    if (!created_parents_.empty()) unregister_created_folders();
    for (auto it = created_parents_.rbegin(); it != created_parents_.rend(); ++it)
        ::rmdir(it->c_str()); // only if empty
    created_parents_.clear();
}

OutputFolder::~OutputFolder()
{
    unregister_staging_path(staging_);
    if (committed_ || keep_staging_) {
        if (!created_parents_.empty()) unregister_created_folders();
        return;
    }
    std::error_code ec;
    fs::remove_all(staging_, ec);
    remove_created_parents();
}

void OutputFolder::write(const std::string& name, const std::string& content)
{
    write(name, [&](std::ostream& out) { out << content; });
}

void OutputFolder::write(const std::string& name, const std::function<void(std::ostream&)>& writer)
{
    throw_if_interrupted();
    fs::path file = staging_ / name;
    std::ofstream out(file, std::ios::binary);
    writer(out);
    out.close();
    if (!out) throw Error(ExitCode::output, file.string() + ": cannot write (disk full?)");
}

void OutputFolder::commit()
{
    throw_if_interrupted();
    if (rename_with(staging_, target_, RENAME_NOREPLACE) == 0) {
        committed_ = true;
        return;
    }
    int error = errno;
    if (error == EINVAL && !lexists(target_) && std::rename(staging_.c_str(), target_.c_str()) == 0) {
        committed_ = true; // a file system without renameat2 flags: a plain rename, checked just before
        return;
    }
    if (error == EEXIST && !overwrite_)
        throw Error(ExitCode::output, target_.string() + ": already exists (it appeared while this run worked); use " +
                                          setting_named("force") + " to replace it");
    if (error != EEXIST && error != ENOTEMPTY)
        throw Error(ExitCode::output,
                    target_.string() + ": cannot move the results into place: " + std::strerror(error));
    // --force: exchange with the existing folder if it is one sphkern wrote, then remove the
    // old one, which now sits at the staging path. What was replaced is checked again after
    // the exchange: another process may have moved a folder of its own to the target in
    // between. Such a folder is exchanged back, never removed, and the signal handler leaves
    // the staging path alone while a folder not ours may sit there.
    const std::string not_ours =
        std::string(": exists and is not a results folder sphkern wrote (no ") + marker_name + " inside); ";
    if (!written_by_sphkern(target_))
        throw Error(ExitCode::output, target_.string() + not_ours + "refusing to replace it");
    unregister_staging_path(staging_);
    if (rename_with(staging_, target_, RENAME_EXCHANGE) != 0) {
        const int error = errno;
        register_staging_path(staging_);
        throw Error(ExitCode::output, target_.string() + ": cannot replace: " + std::strerror(error));
    }
    if (!written_by_sphkern(staging_)) {
        if (rename_with(staging_, target_, RENAME_EXCHANGE) == 0) {
            register_staging_path(staging_);
            throw Error(ExitCode::output, target_.string() + not_ours +
                                              "it was moved there while the results were "
                                              "moved in, and is back in place");
        }
        keep_staging_ = true; // the other folder sits at the staging path: it is never removed
        throw Error(ExitCode::output, target_.string() + not_ours +
                                          "it was moved there while the results were moved "
                                          "in; it is now at " +
                                          staging_.string() + " (nothing was removed)");
    }
    committed_ = true;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

} // namespace sphkern
