// Kernels written as expressions: a JSON file with the shape f(q) (muparser syntax),
// its support, dimensions, parameters and optionally its derivative. W is f as written
// (its constant is the author's, and check judges it), or with "normalise": true f divided
// by its integral per dimension and parameter values, by quadrature (guide-kernel-authors.md).
#pragma once

#include "kernels/kernel_definition.hpp"

#include <filesystem>
#include <memory>

namespace sphkern {

// Throws Error(input) naming the file and the JSON path of what is wrong.
std::shared_ptr<const KernelDefinition> load_expression_kernel(const std::filesystem::path& file);

} // namespace sphkern
