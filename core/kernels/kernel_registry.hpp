// Finds kernel plugins: the build tree's and the install prefix's plugin folders,
// SPHKERN_PLUGIN_PATH, and files named on the command line.
#pragma once

#include "kernels/kernel_plugin.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// The folders searched, in order, that exist.
std::vector<std::filesystem::path> kernel_plugin_folders();

class KernelRegistry {
public:
    // Lists the plugin folders' files and loads every file in `explicit_files` (a broken
    // one is an error). Folder files are loaded only when a command needs them: a name
    // is resolved through the probe cache (or probes, in parallel, of the files whose
    // names are not known yet), and only the file that holds it is loaded.
    static KernelRegistry discover(const std::vector<std::filesystem::path>& explicit_files);

    // Loads only the given files (as `check --plugin` does).
    static KernelRegistry from_files(const std::vector<std::filesystem::path>& files);

    // Every kernel of the plugin folders and files, in discovery order; a broken folder
    // file is skipped with a warning. Two kernels with one name are an error naming both files.
    const std::vector<std::shared_ptr<const KernelDefinition>>& plugins();

    // A kernel by name, by plugin file path (a spec containing '/' or ending in .so),
    // by expression file (ending in .json), or a blend "A+B" of such kernels (at most
    // max_blend_terms; a path that exists as a file is never taken for a blend).
    std::shared_ptr<const KernelDefinition> find(const std::string& spec);

    static constexpr std::size_t max_blend_terms = 16;

private:
    // A file of a plugin folder: its kernel name once known, its definition once loaded.
    struct Candidate {
        std::filesystem::path file;
        std::optional<std::string> name;
        std::shared_ptr<const KernelDefinition> loaded;
        bool broken = false;
    };
    void learn_names();
    std::shared_ptr<const KernelDefinition> load(Candidate& candidate);
    std::shared_ptr<const KernelDefinition> find_single(const std::string& spec);
    std::shared_ptr<const KernelDefinition> find_named(const std::string& spec);
    void add(std::shared_ptr<const KernelDefinition> plugin);

    std::vector<Candidate> candidates_;
    std::vector<std::shared_ptr<const KernelDefinition>> explicit_; // --plugin files and kernels named by path
    std::vector<std::shared_ptr<const KernelDefinition>> all_;
    std::vector<std::pair<std::string, std::shared_ptr<const KernelDefinition>>> blends_;
};

// A plugin library, or an expression kernel if the file ends in .json.
std::shared_ptr<const KernelDefinition> load_kernel_file(const std::filesystem::path& file);

} // namespace sphkern
