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

// Returns an empty string if the descriptor is usable, else why not. Calls the
// plugin's functions at probe points, so run it where a crash cannot hurt.
std::string validate_kernel_descriptor(const sphkern_kernel_descriptor* descriptor);

// Validates a plugin file in a child process (unless the probe cache knows the unchanged
// file) and returns its kernel name. Throws Error(plugin) naming the file and the reason.
std::string probe_kernel_plugin(const std::filesystem::path& file);

// Loads and validates a plugin file; the validation (which runs plugin code) happens
// in a child process first. Throws Error(plugin) naming the file and the reason.
std::shared_ptr<const KernelDefinition> load_kernel_plugin(const std::filesystem::path& file);

// Seconds a plugin may take to load and answer the probes: 10, or SPHKERN_PLUGIN_TIMEOUT.
double plugin_probe_timeout();

} // namespace sphkern
