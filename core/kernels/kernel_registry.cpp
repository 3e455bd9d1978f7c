#include "kernels/kernel_registry.hpp"

#include "support/process/resource_errors.hpp"

#include "kernels/expression_kernel.hpp"
#include "kernels/kernel_blend.hpp"
#include "kernels/plugin_probe_cache.hpp"
#include "support/error.hpp"
#include "support/io/file_spec.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/json_input.hpp"
#include "support/process/interruption.hpp"
#include "support/process/parallel_for.hpp"
#include "support/text/value_checks.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <thread>

namespace sphkern {
namespace fs = std::filesystem;

std::shared_ptr<const KernelDefinition> load_kernel_file(const fs::path& file)
{
    return file.extension() == ".json" ? load_expression_kernel(file) : load_kernel_plugin(file);
}

std::vector<fs::path> kernel_plugin_folders()
{
    std::vector<fs::path> candidates = shipped_plugin_folders();
    if (const char* env = std::getenv("SPHKERN_PLUGIN_PATH")) {
        std::stringstream list(env);
        std::string folder;
        while (std::getline(list, folder, ':'))
            if (!folder.empty()) candidates.emplace_back(folder);
    }
    std::vector<fs::path> folders;
    std::error_code ec;
    for (const auto& c : candidates) {
        if (!fs::is_directory(c, ec)) continue;
        auto canonical = fs::weakly_canonical(c, ec);
        if (std::find(folders.begin(), folders.end(), canonical) == folders.end()) folders.push_back(canonical);
    }
    return folders;
}

namespace {

// One file reached twice (given by its path and found in a plugin folder) is one plugin.
bool same_file(const std::string& a, const std::string& b)
{
    std::error_code ec;
    return a == b || fs::equivalent(a, b, ec);
}

[[noreturn]] void fail_duplicate(const std::string& name, const std::string& a, const std::string& b)
{
    throw Error(ExitCode::plugin, "two plugins are named \"" + name + "\": " + a + " and " + b);
}

} // namespace

void KernelRegistry::add(std::shared_ptr<const KernelDefinition> plugin)
{
    for (const auto& p : explicit_)
        if (p->name == plugin->name) fail_duplicate(plugin->name, p->source, plugin->source);
    explicit_.push_back(std::move(plugin));
}

KernelRegistry KernelRegistry::from_files(const std::vector<fs::path>& files)
{
    KernelRegistry registry;
    for (const auto& f : files) registry.add(load_kernel_file(f));
    PluginProbeCache::instance().save();
    return registry;
}

KernelRegistry KernelRegistry::discover(const std::vector<fs::path>& explicit_files)
{
    KernelRegistry registry;
    std::vector<fs::path> named;
    std::error_code ec;
    for (const auto& file : explicit_files) named.push_back(fs::weakly_canonical(file, ec));
    for (const auto& folder : kernel_plugin_folders()) {
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(folder, ec))
            if ((entry.path().extension() == ".so" || entry.path().extension() == ".json") && !entry.is_directory(ec))
                files.push_back(entry.path());
        // A folder that cannot be listed is not an empty folder: a limit is said, anything else warned.
        if (ec && is_resource_error(ec.value())) fail_resource(ec.value(), folder.string() + ": cannot be listed");
        if (ec) spdlog::warn("{}: cannot be listed: {}", folder.string(), ec.message());
        ec.clear();
        std::sort(files.begin(), files.end());
        for (const auto& file : files)
            if (std::find(named.begin(), named.end(), fs::weakly_canonical(file, ec)) == named.end())
                registry.candidates_.push_back({file, std::nullopt, nullptr, false});
    }
    for (const auto& file : explicit_files) registry.add(load_kernel_file(file));
    PluginProbeCache::instance().save();
    return registry;
}

// The kernel names of every folder file: expression files are read, plugins come from
// the probe cache, and the rest are probed, several at a time.
void KernelRegistry::learn_names()
{
    std::vector<Candidate*> unknown;
    for (auto& c : candidates_) {
        if (c.name || c.broken) continue;
        if (c.file.extension() == ".json") {
            load(c);
            continue;
        }
        if (auto name = PluginProbeCache::instance().passed(c.file)) c.name = *name;
        else unknown.push_back(&c);
    }
    if (unknown.empty()) return;
    std::vector<std::string> failures(unknown.size());
    ParallelFor probes;
    const int threads =
        static_cast<int>(std::min<std::size_t>(unknown.size(), 2 * std::max(1u, std::thread::hardware_concurrency())));
    probes.run(unknown.size(), threads, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end && probes.keep_going(); ++i) {
            try {
                unknown[i]->name = probe_kernel_plugin(unknown[i]->file);
            } catch (const Error& e) {
                if (e.code() != ExitCode::plugin) throw; // an interrupt or a limit of the machine: no plugin's fault
                failures[i] = e.what();
            }
        }
    });
    for (std::size_t i = 0; i < unknown.size(); ++i)
        if (!failures[i].empty()) {
            unknown[i]->broken = true;
            spdlog::warn("skipping {}", failures[i]);
        }
    PluginProbeCache::instance().save();
}

std::shared_ptr<const KernelDefinition> KernelRegistry::load(Candidate& c)
{
    if (c.loaded || c.broken) return c.loaded;
    throw_if_interrupted();
    try {
        c.loaded = load_kernel_file(c.file);
        c.name = c.loaded->name;
    } catch (const ResourceError&) {
        throw; // a limit of the machine, not this file's fault
    } catch (const Error& e) {
        if (e.code() == ExitCode::interrupted) throw;
        c.broken = true;
        spdlog::warn("skipping {}", e.what());
    }
    return c.loaded;
}

const std::vector<std::shared_ptr<const KernelDefinition>>& KernelRegistry::plugins()
{
    learn_names();
    all_.clear();
    for (auto& c : candidates_)
        if (auto p = load(c)) all_.push_back(p);
    for (const auto& p : explicit_)
        if (std::none_of(all_.begin(), all_.end(), [&](const auto& q) { return same_file(q->source, p->source); }))
            all_.push_back(p);
    for (std::size_t i = 0; i < all_.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (all_[i]->name == all_[j]->name) fail_duplicate(all_[i]->name, all_[j]->source, all_[i]->source);
    return all_;
}

std::shared_ptr<const KernelDefinition> KernelRegistry::find(const std::string& spec)
{
    // "A+B+C" is A blended with the blend B+C; a file that exists under that name is a file.
    std::error_code ec;
    if (spec.find('+') != std::string::npos && !fs::exists(spec, ec)) {
        for (const auto& b : blends_)
            if (b.first == spec) return b.second;
        std::vector<std::string> parts;
        std::size_t from = 0;
        for (std::size_t plus; (plus = spec.find('+', from)) != std::string::npos; from = plus + 1)
            parts.push_back(spec.substr(from, plus - from));
        parts.push_back(spec.substr(from));
        if (parts.size() > max_blend_terms)
            fail_input("kernel \"" + spec.substr(0, 60) + (spec.size() > 60 ? "...\"" : "\"") + ": a blend of " +
                       std::to_string(parts.size()) + " kernels, more than the limit of " +
                       std::to_string(max_blend_terms));
        for (const auto& part : parts)
            if (part.empty()) fail_input("kernel \"" + spec + "\": expected A+B with a kernel on each side of '+'");
        // Built from the right without recursion: the last two first.
        std::shared_ptr<const KernelDefinition> blend = find_single(parts.back());
        std::string suffix = parts.back();
        for (std::size_t i = parts.size() - 1; i-- > 0;) {
            suffix = parts[i] + "+" + suffix;
            auto cached =
                std::find_if(blends_.begin(), blends_.end(), [&](const auto& b) { return b.first == suffix; });
            if (cached != blends_.end()) {
                blend = cached->second;
                continue;
            }
            blend = make_blend(Kernel(find_single(parts[i])), Kernel(blend));
            blends_.emplace_back(suffix, blend);
        }
        return blend;
    }
    return find_single(spec);
}

std::shared_ptr<const KernelDefinition> KernelRegistry::find_single(const std::string& spec)
{
    if (spec.ends_with(".json")) {
        auto canonical = fs::absolute(spec).lexically_normal().string();
        for (const auto& p : explicit_)
            if (p->source == canonical) return p;
        auto kernel = load_expression_kernel(spec);
        add(kernel);
        return kernel;
    }
    if (looks_like_path(spec, ".so")) {
        std::error_code ec;
        auto canonical = fs::absolute(spec).lexically_normal().string();
        for (const auto& p : explicit_)
            if (p->source == canonical) return p;
        auto plugin = load_kernel_plugin(spec);
        PluginProbeCache::instance().save();
        add(plugin);
        return plugin;
    }
    // A name: the explicit files first, then the folders' files, whose names the cache knows
    // (or probes learn); two files with the name are an error, whichever is asked for.
    learn_names();
    if (auto found = find_named(spec)) return found;
    // No file claims the name: a cached name may be stale (the same size and times, another
    // kernel). Every file is loaded, which puts its descriptor's name in the cache, and asked again.
    for (auto& c : candidates_) load(c);
    PluginProbeCache::instance().save();
    if (auto found = find_named(spec)) return found;
    std::vector<std::string> names;
    for (const auto& p : explicit_) names.push_back(p->name);
    for (const auto& c : candidates_)
        if (c.name) names.push_back(*c.name);
    std::string message = "unknown kernel \"" + spec + "\"" + did_you_mean(spec, names);
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    fail_unknown(message + "; known kernels: " + (list.empty() ? "none found (no plugin folder)" : list));
}

// The kernel named `spec`, or null. A folder file is taken by its descriptor's name: one whose
// cached name matches is loaded first (the load replaces a stale cached name).
std::shared_ptr<const KernelDefinition> KernelRegistry::find_named(const std::string& spec)
{
    std::shared_ptr<const KernelDefinition> found;
    std::string found_source;
    for (const auto& p : explicit_)
        if (p->name == spec) found = p, found_source = p->source;
    for (auto& c : candidates_) {
        if (!c.name || *c.name != spec) continue;
        auto loaded = load(c);
        const std::string source = fs::absolute(c.file).lexically_normal().string();
        if (!loaded || loaded->name != spec || (found && same_file(found_source, source))) continue;
        if (found) fail_duplicate(spec, found_source, source);
        found = loaded;
        found_source = source;
    }
    return found;
}

} // namespace sphkern
