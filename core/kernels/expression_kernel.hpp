// Kernels written as expressions: a JSON file with the shape f(q) (muparser syntax),
// its support, dimensions, parameters and optionally its derivative; sphkern computes
// the normalisation per dimension by quadrature (README, "Expression kernels").
#pragma once

#include "kernels/kernel_definition.hpp"

#include <filesystem>
#include <memory>

namespace sphkern {

// Throws Error(input) naming the file and the JSON path of what is wrong.
std::shared_ptr<const KernelDefinition> load_expression_kernel(const std::filesystem::path& file);

} // namespace sphkern
