// Remembers which plugin files passed the probe, so that a command does not fork a
// child for every plugin every time. An entry holds the file's size, modification and
// status-change times, inode and device: a changed file is probed again (a file rewritten in
// place with its old size and mtime still has a new ctime, which no user can set back). The cache lives in
// $XDG_CACHE_HOME/sphkern (or ~/.cache/sphkern); a missing, unreadable or corrupt
// cache is ignored, and a cache that cannot be written is not an error.
#pragma once

#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <sys/stat.h>

namespace sphkern {

class PluginProbeCache {
public:
    // The process's cache, read on first use.
    static PluginProbeCache& instance();

    // The kernel name of `file` if it passed the probe and has not changed since. With `opened`
    // (fstat of a descriptor), the file judged is that open file, not what the path names now.
    std::optional<std::string> passed(const std::filesystem::path& file, const struct stat* opened = nullptr);
    void record(const std::filesystem::path& file, const std::string& kernel_name, const struct stat* opened = nullptr);
    // Drops the entry of `file` (its kernel turned out to be another one): the next use probes it.
    void forget(const std::filesystem::path& file);
    void save(); // writes the file if something was recorded

    // Where the cache is kept (empty if neither XDG_CACHE_HOME nor HOME is set).
    static std::filesystem::path location();

private:
    PluginProbeCache();
    struct Entry {
        long long size = 0, mtime_ns = 0, ctime_ns = 0;
        unsigned long long inode = 0, device = 0;
        std::string name;
        bool operator==(const Entry& o) const
        {
            return size == o.size && mtime_ns == o.mtime_ns && ctime_ns == o.ctime_ns && inode == o.inode &&
                   device == o.device;
        }
    };
    static std::optional<Entry> describe(const std::filesystem::path& file);
    static std::optional<Entry> describe(const struct stat& status);
    std::mutex mutex_;
    std::map<std::string, Entry> entries_;
    bool changed_ = false;
};

} // namespace sphkern
