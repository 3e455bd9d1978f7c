// The parameter sweeps: both errors over (k, parameter) and the kernels designed there.
#include "study/sections/sections.hpp"

#include "support/process/interruption.hpp"

#include <algorithm>

namespace sphkern {

namespace {

// Both errors over the (k, parameter) grid.
void sweep_grid(const StudySweep& sweep, const Kernel& kernel, const Lattice& lattice, double k_max, SweepCase& c)
{
    for (int i = 0; i < sweep.samples; ++i) {
        throw_if_interrupted();
        double value = sweep.min + (sweep.max - sweep.min) * i / (sweep.samples - 1);
        auto values = sweep.parameters;
        values[sweep.parameter] = value;
        Kernel at(kernel.shared_definition(), values);
        HydrostaticErrors errors(at, lattice, 0, c.a_p, lattice.gravity, k_max);
        c.values.push_back(value);
        c.rho.emplace_back();
        c.gradp.emplace_back();
        for (double k : c.ks) {
            auto v = errors.at(k);
            c.rho.back().push_back(v.eps_rho);
            c.gradp.back().push_back(v.eps_gradp);
        }
    }
}

SweepCase sweep_case(const Study& study, const StudyInputs& inputs, std::size_t s, std::size_t l)
{
    const StudySweep& sweep = study.sweeps[s];
    const Kernel& kernel = inputs.sweep_kernels[s];
    const Lattice& lattice = inputs.lattices[l];
    SweepCase c;
    c.lattice = lattice.name;
    c.kernel = kernel.name();
    c.parameter = sweep.parameter;
    c.ap_name = study.volume_coefficients[0].name;
    c.a_p = inputs.a_p[l][0];
    // Sweeps keep one k grid per lattice: the window of the sweep's kernel at its declared parameters.
    const auto [k_min, k_max] = inputs.window(l, inputs.kernels.size() + s, 0, c.a_p);
    DesignProblem problem{&lattice, 0, c.a_p, lattice.gravity, k_min, k_max, sweep.parameter, sweep.min, sweep.max};
    c.design = at_source(study_source(study, sweep.json_path), [&] { return design_kernel(kernel, problem); });
    const int k_samples = std::min(study.samples, 201);
    for (int j = 0; j < k_samples; ++j) c.ks.push_back(k_min + (k_max - k_min) * j / (k_samples - 1));
    sweep_grid(sweep, kernel, lattice, k_max, c);
    for (const auto& solution : c.design.solutions) {
        auto values = sweep.parameters;
        values[sweep.parameter] = solution.parameter;
        Kernel designed(kernel.shared_definition(), values);
        HydrostaticErrors errors(designed, lattice, 0, c.a_p, lattice.gravity, k_max);
        c.designed_acceptance.push_back(evaluate_acceptance(errors, k_min, k_max, study.epsilon));
    }
    return c;
}

} // namespace

void run_sweep_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    for (std::size_t s = 0; s < study.sweeps.size(); ++s)
        for (std::size_t l = 0; l < inputs.lattices.size(); ++l) {
            if (!inputs.sweep_kernels[s].supports(inputs.lattices[l].dimension)) continue;
            results.sweeps.push_back(sweep_case(study, inputs, s, l));
            throw_if_interrupted();
        }
}

} // namespace sphkern
