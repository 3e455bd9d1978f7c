#include "study/study_inputs.hpp"

#include "analysis/resolution_axis.hpp"
#include "support/error.hpp"

#include <sstream>

namespace sphkern {

namespace {

std::string support_key(double R)
{
    std::ostringstream s;
    s << R;
    return s.str();
}

} // namespace

StudyInputs load_study_inputs(const Study& study, KernelRegistry& registry)
{
    StudyInputs inputs;
    for (const auto& k : study.kernels) {
        try {
            inputs.kernels.push_back(Kernel(registry.find(k.spec), k.parameters));
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": " + k.json_path + ": " + e.what());
        }
    }
    auto& lattices = inputs.lattices;
    for (std::size_t i = 0; i < study.lattices.size(); ++i) {
        try {
            lattices.push_back(load_lattice(study.lattices[i]));
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": /lattices/" + std::to_string(i) + ": " + e.what());
        }
    }
    // One name, one table: two lattices or kernels that print alike would be merged.
    for (std::size_t i = 0; i < lattices.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (lattices[i].name == lattices[j].name)
                fail_input(study.file + ": /lattices/" + std::to_string(i) + ": lattice name \"" + lattices[i].name +
                           "\" is already used by /lattices/" + std::to_string(j) + "; give each lattice its own name");
    const auto& kernels = inputs.kernels;
    for (std::size_t i = 0; i < kernels.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (kernels[i].label() == kernels[j].label())
                fail_input(study.file + ": " + study.kernels[i].json_path + ": kernel \"" + kernels[i].label() +
                           "\" is listed twice (also at " + study.kernels[j].json_path + ")");
    for (std::size_t i = 0; i < kernels.size(); ++i)
        for (const auto& l : lattices)
            try {
                kernels[i].require_dimension(l.dimension, l.name);
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": " + study.kernels[i].json_path + ": " + e.what());
            }
    return inputs;
}

EvaluationMode evaluation_mode(const Study& study, const StudyMode& mode, const Kernel& kernel)
{
    EvaluationMode m;
    if (mode.shells_by_support.empty()) return m;
    auto it = mode.shells_by_support.find(support_key(kernel.support()));
    if (it == mode.shells_by_support.end())
        fail_input(study.file + ": " + mode.json_path + "/shells: no shell list for kernel " + kernel.name() +
                   " with support R = " + support_key(kernel.support()) + ", expected a key \"" +
                   support_key(kernel.support()) + "\"");
    m.shell_radii = it->second;
    m.continue_past_support = mode.continues(kernel.name());
    return m;
}

std::pair<double, double> study_window(const Study& study, const Kernel& kernel, const Lattice& lattice, int site,
                                       double a_p)
{
    try {
        return k_window(parse_axis(study.axis, "axis"), study.k_min, study.k_max, kernel, lattice, site, a_p, "window");
    } catch (const Error& e) {
        throw Error(e.code(), study.file + ": /k: " + e.what());
    }
}

double study_volume_coefficient(const Study& study, const Lattice& lattice, std::size_t index)
{
    try {
        return lattice.volume_coefficient(study.volume_coefficients[index]);
    } catch (const Error& e) {
        throw Error(e.code(), study.file + ": /volume_coefficients/" + std::to_string(index) + ": " + e.what());
    }
}

} // namespace sphkern
