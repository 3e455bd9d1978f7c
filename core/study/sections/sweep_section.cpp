// The parameter sweeps: both errors over (k, parameter) and the kernels designed there.
#include "study/sections/sections.hpp"

#include "support/error.hpp"
#include "support/interruption.hpp"

#include <algorithm>
#include <optional>

namespace sphkern {

void run_sweep_section(const Study& study, KernelRegistry& registry, const StudyInputs& inputs, StudyResults& results)
{
    for (const auto& sweep : study.sweeps) {
        std::optional<Kernel> kernel;
        try {
            kernel.emplace(registry.find(sweep.kernel), sweep.parameters);
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": " + sweep.json_path + ": " + e.what());
        }
        for (const auto& lattice : inputs.lattices) {
            if (!kernel->supports(lattice.dimension)) continue;
            SweepCase c;
            c.lattice = lattice.name;
            c.kernel = kernel->name();
            c.parameter = sweep.parameter;
            c.ap_name = study.volume_coefficients[0];
            c.a_p = lattice.volume_coefficient(c.ap_name);
            // Sweeps keep one k grid per lattice: the window of the sweep's kernel at its declared parameters.
            const auto [k_min, k_max] = study_window(study, *kernel, lattice, 0, c.a_p);
            DesignProblem problem{&lattice, 0, c.a_p, lattice.gravity, k_min, k_max, sweep.parameter, sweep.min, sweep.max};
            try {
                c.design = design_kernel(*kernel, problem);
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": " + sweep.json_path + ": " + e.what());
            }
            const int k_samples = std::min(study.samples, 201);
            for (int j = 0; j < k_samples; ++j) c.ks.push_back(k_min + (k_max - k_min) * j / (k_samples - 1));
            for (int i = 0; i < sweep.samples; ++i) {
                throw_if_interrupted();
                double value = sweep.min + (sweep.max - sweep.min) * i / (sweep.samples - 1);
                auto values = sweep.parameters;
                values[sweep.parameter] = value;
                Kernel at(kernel->shared_definition(), values);
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
            for (const auto& s : c.design.solutions) {
                auto values = sweep.parameters;
                values[sweep.parameter] = s.parameter;
                Kernel designed(kernel->shared_definition(), values);
                HydrostaticErrors errors(designed, lattice, 0, c.a_p, lattice.gravity, k_max);
                c.designed_acceptance.push_back(evaluate_acceptance(errors, k_min, k_max, study.epsilon));
            }
            results.sweeps.push_back(std::move(c));
            throw_if_interrupted();
        }
    }
}

} // namespace sphkern
