// The particle-set function of the Python module, in a file of its own.
#pragma once

#include "kernels/kernel.hpp"

#include <nlohmann/json_fwd.hpp>
#include <pybind11/pybind11.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

using KernelOf = Kernel (*)(const std::string& spec, const pybind11::object& params);
using ToPython = pybind11::object (*)(const nlohmann::json& document);

void bind_particles(pybind11::module_& m, KernelOf kernel_of, ToPython to_python);

// sphkern.assess on a particle file: a code's setting judged on the set (`assess KERNEL FILE`),
// or its parameter swept over a range (the keyword `<parameter>_range`).
struct FileAssess {
    std::optional<std::string> code;
    std::optional<double> value;
    double epsilon = 0.01;
    std::optional<std::vector<double>> box;
    std::optional<std::string> array, neighbours_by;
    bool bias_correction = false;
    int threads = 0, steps = 10;
    std::map<std::string, std::vector<double>> ranges; // "eta" -> [A, B], those given
};
pybind11::object assess_particle_file(const Kernel& kernel, const std::string& path, const FileAssess& given,
                                      ToPython to_python);

} // namespace sphkern
