// Kernel plugins: validating a descriptor and loading a plugin library into a
// KernelDefinition whose functions keep the library mapped while they are in use.
#pragma once

#include "kernels/kernel_definition.hpp"

#include <sphkern/kernel_plugin.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sphkern {

// A descriptor of ABI 1 or 2 in the ABI 2 form, with the extensions it provides.
struct PluginDescriptor {
    uint32_t abi_major = 0, abi_minor = 0;
    sphkern_kernel_descriptor fields{};
    const sphkern_second_derivative* second = nullptr;
    const sphkern_fourier_transform* fourier = nullptr;
    const sphkern_fused_evaluation* fused = nullptr;
};

// How much of a descriptor to check: its fields only, or also its functions' values at the
// probe points (61 q x 4 k in each dimension), which runs plugin code.
enum class DescriptorCheck { fields, with_functions };

// Reads what a plugin's entry function returned into `out` (layout, then fields, then the
// functions); returns an empty string if the descriptor is usable, else why not. With the
// functions it calls plugin code, so run it where a crash cannot hurt.
std::string read_kernel_descriptor(const void* raw, PluginDescriptor& out,
                                   DescriptorCheck check = DescriptorCheck::with_functions);

// Validates a plugin file in a child process (unless the probe cache knows the unchanged
// file) and returns its kernel name. Throws Error(plugin) naming the file and the reason.
std::string probe_kernel_plugin(const std::filesystem::path& file);

// Loads and validates a plugin file; the validation (which runs plugin code) happens
// in a child process first. Throws Error(plugin) naming the file and the reason.
std::shared_ptr<const KernelDefinition> load_kernel_plugin(const std::filesystem::path& file);

// Seconds a plugin may take to load and answer the probes: 10, or SPHKERN_PLUGIN_TIMEOUT.
double plugin_probe_timeout();

} // namespace sphkern
