// What every binding file of the module shares: the one kernel registry (the shipped plugins
// and the files loaded into the module), kernels made from it, and JSON documents as Python objects.
#pragma once

#include "kernels/kernel.hpp"
#include "kernels/kernel_registry.hpp"
#include "particles/particle_set.hpp"
#include "requests/evaluation_inputs.hpp"

#include <nlohmann/json_fwd.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// Kernels are resolved lazily: one resolution at a time, under this lock.
std::mutex& registry_mutex();
KernelRegistry& registry(); // with the lock held

// A kernel's parameters as given: None, or a dict of names to numbers.
std::map<std::string, double> parameters_of(const pybind11::object& params);

// A kernel by name or file, with its parameters (a dict of names to numbers, or None).
Kernel kernel_of(const std::string& spec, const pybind11::object& params);

// a_p as given: a name the lattice offers or a number.
VolumeCoefficientInput ap_input(const pybind11::object& a_p);

// A particle file as the command line reads it (`box` as --box, `array` as --array, ...),
// checked and named as Python names them. Call without the GIL.
ParticleSet load_particle_file(const std::string& path, const std::optional<std::vector<double>>& box,
                               const std::optional<std::string>& array, const std::optional<int>& dim,
                               const std::optional<double>& particle_radius);

// A set's positions as an (N, D) array.
pybind11::array_t<double> positions_array(const ParticleSet& set);

// A document as Python objects (dicts, lists, numbers, strings, None).
pybind11::object to_python(const nlohmann::json& document);

} // namespace sphkern
