// The free-surface section: a profile below the surface per lattice, kernel and form.
#include "study/sections/sections.hpp"

#include "support/error.hpp"
#include "support/interruption.hpp"

namespace sphkern {

void run_surface_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    if (!study.surface) return;
    const auto& surface = *study.surface;
    const std::string ap_name = surface.volume_coefficient.empty() ? study.volume_coefficients[0] : surface.volume_coefficient;
    for (const auto& lattice : inputs.lattices) {
        double a_p;
        try {
            a_p = lattice.volume_coefficient(ap_name);
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": /surface/volume_coefficient: " + e.what());
        }
        for (const auto& kernel : inputs.kernels) {
            double k = 0;
            if (surface.k) {
                k = *surface.k;
            } else { // the best k of condition (22) in the first mode, for this a_p, in the study's window
                const auto [k_min, k_max] = study_window(study, kernel, lattice, 0, a_p);
                HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, k_max,
                                         evaluation_mode(study, study.modes[0], kernel));
                k = evaluate_acceptance(errors, k_min, k_max, study.epsilon).best_k;
            }
            for (const auto& form : surface.forms) {
                SurfaceCase c{lattice.name, kernel.label(), form, ap_name, a_p, k, {}};
                try {
                    c.profile = surface_profile(kernel, lattice, 0, a_p, lattice.gravity, k, surface.layers,
                                                parse_gradient_form(form));
                } catch (const Error& e) {
                    throw Error(e.code(), study.file + ": /surface: " + e.what());
                }
                results.surface.push_back(std::move(c));
                throw_if_interrupted();
            }
        }
    }
}

} // namespace sphkern
