#include "kernels/plugin_probe_cache.hpp"

#include "support/io/atomic_file.hpp"
#include "support/io/json_input.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <sys/stat.h>

#ifndef SPHKERN_VERSION
#define SPHKERN_VERSION "0"
#endif

namespace sphkern {
namespace fs = std::filesystem;

namespace {

// A new sphkern may validate differently: its cache is its own.
constexpr const char* cache_format = "sphkern " SPHKERN_VERSION " plugin probes 2";

std::string key_of(const fs::path& file)
{
    std::error_code ec;
    auto canonical = fs::weakly_canonical(fs::absolute(file, ec), ec);
    return (ec ? fs::absolute(file) : canonical).string();
}

} // namespace

fs::path PluginProbeCache::location()
{
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg && fs::path(xdg).is_absolute())
        return fs::path(xdg) / "sphkern" / "plugin-probes.json";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".cache" / "sphkern" / "plugin-probes.json";
    return {};
}

PluginProbeCache& PluginProbeCache::instance()
{
    static PluginProbeCache cache;
    return cache;
}

PluginProbeCache::PluginProbeCache()
{
    const fs::path file = location();
    std::error_code ec;
    if (file.empty() || !fs::is_regular_file(file, ec)) return;
    try {
        auto document = read_json_file(file);
        if (document.value("format", "") != cache_format) return;
        for (const auto& [path, e] : document.at("plugins").items())
            entries_[path] = {e.at("size").get<long long>(),
                              e.at("mtime_ns").get<long long>(),
                              e.at("ctime_ns").get<long long>(),
                              e.at("inode").get<unsigned long long>(),
                              e.at("device").get<unsigned long long>(),
                              e.at("name").get<std::string>()};
    } catch (const std::exception& e) { // a corrupt cache is only a missed shortcut
        spdlog::debug("ignoring the plugin probe cache {}: {}", file.string(), e.what());
        entries_.clear();
    }
}

std::optional<PluginProbeCache::Entry> PluginProbeCache::describe(const fs::path& file)
{
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) return std::nullopt;
    return describe(st);
}

std::optional<PluginProbeCache::Entry> PluginProbeCache::describe(const struct stat& st)
{
    if (!S_ISREG(st.st_mode)) return std::nullopt;
    Entry e;
    e.size = st.st_size;
    e.mtime_ns = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
    e.ctime_ns = static_cast<long long>(st.st_ctim.tv_sec) * 1000000000LL + st.st_ctim.tv_nsec;
    e.inode = st.st_ino;
    e.device = st.st_dev;
    return e;
}

std::optional<std::string> PluginProbeCache::passed(const fs::path& file, const struct stat* opened)
{
    auto now = opened ? describe(*opened) : describe(file);
    if (!now) return std::nullopt;
    std::lock_guard lock(mutex_);
    auto it = entries_.find(key_of(file));
    if (it == entries_.end() || !(it->second == *now)) return std::nullopt;
    return it->second.name;
}

void PluginProbeCache::record(const fs::path& file, const std::string& kernel_name, const struct stat* opened)
{
    auto now = opened ? describe(*opened) : describe(file);
    if (!now) return;
    now->name = kernel_name;
    std::lock_guard lock(mutex_);
    entries_[key_of(file)] = *now;
    changed_ = true;
}

void PluginProbeCache::forget(const fs::path& file)
{
    std::lock_guard lock(mutex_);
    if (entries_.erase(key_of(file)) > 0) changed_ = true;
}

void PluginProbeCache::save()
{
    std::lock_guard lock(mutex_);
    const fs::path file = location();
    if (!changed_ || file.empty()) return;
    nlohmann::json plugins = nlohmann::json::object();
    for (const auto& [path, e] : entries_)
        plugins[path] = {{"size", e.size},   {"mtime_ns", e.mtime_ns}, {"ctime_ns", e.ctime_ns},
                         {"inode", e.inode}, {"device", e.device},     {"name", e.name}};
    try {
        std::error_code ec;
        fs::create_directories(file.parent_path(), ec);
        write_file_atomically(file, [&](std::ostream& out) {
            out << nlohmann::json{{"format", cache_format}, {"plugins", plugins}}.dump(1) << "\n";
        });
        changed_ = false;
    } catch (const std::exception& e) {
        spdlog::debug("the plugin probe cache was not written: {}", e.what());
    }
}

} // namespace sphkern
