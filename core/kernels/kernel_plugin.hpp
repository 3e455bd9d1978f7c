// A loaded kernel plugin library: its validated descriptor, its metadata copied into
// C++ types, and the library handle that keeps its code mapped while it is in use.
#pragma once

#include <sphkern/kernel_plugin.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace boost::dll {
class shared_library;
}

namespace sphkern {

struct KernelParameter {
    std::string name;
    std::string description;
    double default_value;
    double min_value;
    double max_value;
};

struct KernelPlugin {
    std::filesystem::path file;
    std::shared_ptr<boost::dll::shared_library> library; // keeps `descriptor` valid
    const sphkern_kernel_descriptor* descriptor = nullptr;

    std::string name;
    std::string title;
    std::string reference;
    double support = 0;
    std::vector<int> dimensions;
    std::vector<KernelParameter> parameters;
    std::vector<double> breakpoints;
    bool separate_derivative = false;

    bool supports(int dim) const;
    std::string dimensions_text() const; // "1,2,3"
};

// Returns an empty string if the descriptor is usable, else why not. Calls the
// plugin's functions at probe points, so run it where a crash cannot hurt.
std::string validate_kernel_descriptor(const sphkern_kernel_descriptor* descriptor);

// Loads and validates a plugin file; the validation (which runs plugin code) happens
// in a child process first. Throws Error(plugin) naming the file and the reason.
std::shared_ptr<const KernelPlugin> load_kernel_plugin(const std::filesystem::path& file);

// Seconds a plugin may take to load and answer the probes: 10, or SPHKERN_PLUGIN_TIMEOUT.
double plugin_probe_timeout();

} // namespace sphkern
