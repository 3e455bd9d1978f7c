// The kernels request (`sphkern kernels`, sphkern.kernels()): every kernel plugin found.
#pragma once

#include "kernels/kernel_registry.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// One entry per plugin (name, support, dimensions, parameters, reference, file).
nlohmann::json kernels_listing(KernelRegistry& registry);

// The text `sphkern kernels` prints: a table of the same.
void print_kernels(KernelRegistry& registry);

} // namespace sphkern
