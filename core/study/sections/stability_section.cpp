// The stability section: per kernel and lattice, the stable k intervals, the dispersion
// curves along the high-symmetry path, and where they overlap condition (22).
#include "study/sections/sections.hpp"

#include "analysis/code_conventions.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/stability_scan.hpp"
#include "support/error.hpp"
#include "support/parallel_for.hpp"
#include "support/progress.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

namespace sphkern {

void run_stability_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    if (!study.stability) return;
    const auto& spec = *study.stability;
    std::vector<StabilityCase> cases(inputs.lattices.size() * inputs.kernels.size());
    Progress progress("stability", cases.size());
    std::mutex progress_mutex;
    auto run_case = [&](std::size_t index) {
        const auto& lattice = inputs.lattices[index / inputs.kernels.size()];
        const auto& kernel = inputs.kernels[index % inputs.kernels.size()];
        StabilityCase& c = cases[index];
        c.lattice = lattice.name;
        c.kernel_label = kernel.label();
        c.gamma = spec.gamma;
        c.h_model = spec.h_model;
        const HModel h_model = parse_h_model(spec.h_model, "stability.h_model");
        c.over_k.horizon = spec.horizon; // also for a lattice that is refused
        // The bulk cases of the first automatic mode: their windows and condition (22).
        std::vector<const StudyCase*> accurate;
        for (const auto& b : results.cases)
            if (b.lattice == lattice.name && b.kernel_label == c.kernel_label && b.automatic &&
                (accurate.empty() || b.mode == accurate.front()->mode))
                accurate.push_back(&b);
        double k_min = INFINITY, k_max = -INFINITY;
        if (spec.k_min) {
            k_min = *spec.k_min;
            k_max = *spec.k_max;
        } else { // the union of the study's windows over its volume coefficients
            for (std::size_t a = 0; a < study.volume_coefficients.size(); ++a) {
                const auto [from, to] =
                    study_window(study, kernel, lattice, 0, study_volume_coefficient(study, lattice, a));
                k_min = std::min(k_min, from);
                k_max = std::max(k_max, to);
            }
        }
        c.path_k = spec.path_k ? *spec.path_k : !accurate.empty() ? accurate.front()->acceptance.best_k
                                                                   : 0.5 * (k_min + k_max);
        try {
            c.over_k = stability_over_k(kernel, lattice, k_min, k_max, spec.steps, spec.gamma, spec.grid, 1, spec.horizon,
                                        h_model);
            const Dispersion at(kernel, lattice, c.path_k, spec.gamma, h_model);
            c.path = dispersion_along_path(at, reciprocal_lattice(lattice), spec.path_points);
        } catch (const Error& e) {
            if (e.code() != ExitCode::input) throw;
            c.refused = e.what(); // a lattice whose sites are no common equilibrium
        }
        if (c.refused.empty())
            for (const auto* b : accurate) {
                StabilityOverlap o{b->ap_name, b->acceptance.intervals, accurate_and_stable(b->acceptance.intervals, c.over_k), {}, {}};
                const HydrostaticErrors errors(kernel, lattice, b->sites.empty() ? 0 : b->sites.front(), b->a_p,
                                               lattice.gravity, std::max(k_max, b->k_max));
                o.recommended = recommend_k(o.both, b->k_min, b->k_max, errors);
                if (o.recommended.found)
                    for (const auto& convention : code_conventions())
                        o.in_conventions.push_back(
                            in_convention(convention, kernel, lattice.dimension, b->a_p, o.recommended.k));
                c.overlap.push_back(std::move(o));
            }
        std::lock_guard lock(progress_mutex);
        progress.step(kernel.name() + " on " + lattice.name);
    };
    // One case per thread at a time, taken in turn: their costs differ by orders of magnitude.
    std::atomic<std::size_t> next{0};
    ParallelFor pool;
    pool.run(cases.size(), static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
             [&](int, std::size_t, std::size_t) {
                 for (std::size_t i; pool.keep_going() && (i = next++) < cases.size();) run_case(i);
             });
    for (auto& c : cases) results.stability.push_back(std::move(c));
}

} // namespace sphkern
