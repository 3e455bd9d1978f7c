// The free-surface section: a profile below the surface per lattice, kernel and form.
#include "study/sections/sections.hpp"

#include "support/process/interruption.hpp"

namespace sphkern {

void run_surface_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    if (!study.surface) return;
    const auto& surface = *study.surface;
    const std::string ap_name =
        surface.volume_coefficient ? surface.volume_coefficient->name : study.volume_coefficients[0].name;
    for (std::size_t l = 0; l < inputs.lattices.size(); ++l) {
        const Lattice& lattice = inputs.lattices[l];
        const double a_p = inputs.surface_a_p[l];
        for (std::size_t i = 0; i < inputs.kernels.size(); ++i) {
            const Kernel& kernel = inputs.kernels[i];
            double k = 0;
            if (surface.k) {
                k = *surface.k;
            } else { // the best k of condition (22) in the first mode, for this a_p, in the study's window
                const auto [k_min, k_max] = inputs.window(l, i, 0, a_p);
                HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, k_max, inputs.evaluation[0][i]);
                k = evaluate_acceptance(errors, k_min, k_max, study.epsilon).best_k;
            }
            for (const auto form : surface.forms) {
                SurfaceCase c{lattice.name, kernel.label(), gradient_form_name(form), ap_name, a_p, k, {}};
                c.profile = at_source(study_source(study, "/surface"), [&] {
                    return surface_profile(kernel, lattice, 0, a_p, lattice.gravity, k, surface.layers, form);
                });
                results.surface.push_back(std::move(c));
                throw_if_interrupted();
            }
        }
    }
}

} // namespace sphkern
