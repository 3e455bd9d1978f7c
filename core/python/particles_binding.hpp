// The particle-set function of the Python module, in a file of its own.
#pragma once

#include "kernels/kernel.hpp"

#include <nlohmann/json_fwd.hpp>
#include <pybind11/pybind11.h>

#include <string>

namespace sphkern {

using KernelOf = Kernel (*)(const std::string& spec, const pybind11::object& params);
using ToPython = pybind11::object (*)(const nlohmann::json& document);

void bind_particles(pybind11::module_& m, KernelOf kernel_of, ToPython to_python);

} // namespace sphkern
