// A plugin file opened once, so that the probe (in a child) and the load (here) read the
// same file: both go through /proc/self/fd/N, and a file replaced or rewritten between
// them is never run unprobed.
#pragma once

#include <filesystem>
#include <string>
#include <sys/stat.h>

namespace sphkern {

class PluginFile {
public:
    // Throws Error(plugin) naming the file if it is missing, not a regular file or too large.
    explicit PluginFile(const std::filesystem::path& file);
    ~PluginFile(); // closes the descriptor unless keep() was called
    PluginFile(const PluginFile&) = delete;
    PluginFile& operator=(const PluginFile&) = delete;

    const std::string& name() const { return name_; }          // as given, for messages
    const std::string& loader_path() const { return loader_; } // "/proc/self/fd/N"
    int descriptor() const { return fd_; }
    const struct stat& status() const { return status_; }
    // False if the file was written to since it was opened (size, mtime or ctime changed).
    bool unchanged() const;
    // The library loaded from loader_path() is known to the loader by that name: the descriptor
    // stays open for the process's life, so that no other file ever gets the same name.
    void keep() { kept_ = true; }

private:
    std::string name_, loader_;
    int fd_ = -1;
    struct stat status_ {};
    bool kept_ = false;
};

} // namespace sphkern
