// A kernel's description as JSON: what `kernels --json` prints and the Python module returns.
#pragma once

#include "kernels/kernel_definition.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

nlohmann::json kernel_json(const KernelDefinition& kernel);

} // namespace sphkern
