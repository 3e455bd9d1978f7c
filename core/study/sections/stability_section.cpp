// The stability section: per kernel and lattice, the stable k intervals, the dispersion
// curves along the high-symmetry path, and where they overlap condition (22).
#include "study/sections/sections.hpp"

#include "analysis/code_conventions.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/stability_scan.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/progress.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

namespace sphkern {

namespace {

// The bulk cases of the first automatic mode, one per a_p: their windows and condition (22).
std::vector<const StudyCase*> accurate_cases(const Study& study, const StudyResults& results, std::size_t l, std::size_t k)
{
    std::vector<const StudyCase*> accurate;
    if (const auto mode = first_automatic_mode(study))
        for (std::size_t a = 0; a < study.volume_coefficients.size(); ++a)
            if (const auto* c = find_case(results, {l, k, a, *mode})) accurate.push_back(c);
    return accurate;
}

// The k scanned: the section's, or the union of the study's windows over its volume coefficients.
std::pair<double, double> scanned_k(const StudyStability& spec, const StudyInputs& inputs, std::size_t l, std::size_t k)
{
    if (spec.k_min) return {*spec.k_min, *spec.k_max};
    double k_min = INFINITY, k_max = -INFINITY;
    for (double a_p : inputs.a_p[l]) {
        const auto [from, to] = inputs.window(l, k, 0, a_p);
        k_min = std::min(k_min, from);
        k_max = std::max(k_max, to);
    }
    return {k_min, k_max};
}

// Where the accurate k of a bulk case are stable too, and the k recommended there.
StabilityOverlap overlap(const StudyCase& b, const StabilityCase& c, const Kernel& kernel, const Lattice& lattice,
                         double k_max)
{
    StabilityOverlap o{b.ap_name, b.acceptance.intervals, accurate_and_stable(b.acceptance.intervals, c.over_k), {}, {}};
    const HydrostaticErrors errors(kernel, lattice, b.sites.empty() ? 0 : b.sites.front(), b.a_p, lattice.gravity,
                                   std::max(k_max, b.k_max));
    o.recommended = recommend_k(o.both, b.k_min, b.k_max, errors);
    if (o.recommended.found)
        for (const auto& convention : code_conventions())
            o.in_conventions.push_back(in_convention(convention, kernel, lattice.dimension, b.a_p, o.recommended.k));
    return o;
}

StabilityCase stability_case(const Study& study, const StudyInputs& inputs, const StudyResults& results, std::size_t l,
                             std::size_t k)
{
    const auto& spec = *study.stability;
    const Lattice& lattice = inputs.lattices[l];
    const Kernel& kernel = inputs.kernels[k];
    StabilityCase c;
    c.lattice = lattice.name;
    c.kernel_label = kernel.label();
    c.gamma = spec.gamma;
    c.h_model = h_model_name(spec.h_model);
    c.over_k.horizon = spec.horizon; // also for a lattice that is refused
    const auto accurate = accurate_cases(study, results, l, k);
    const auto [k_min, k_max] = scanned_k(spec, inputs, l, k);
    c.path_k = spec.path_k ? *spec.path_k : !accurate.empty() ? accurate.front()->acceptance.best_k : 0.5 * (k_min + k_max);
    try {
        c.over_k = stability_over_k(kernel, lattice, k_min, k_max, spec.steps, spec.gamma, spec.grid, 1, spec.horizon,
                                    spec.h_model);
        const Dispersion at(kernel, lattice, c.path_k, spec.gamma, spec.h_model);
        c.path = dispersion_along_path(at, reciprocal_lattice(lattice), spec.path_points);
    } catch (const Error& e) {
        if (e.code() != ExitCode::input) throw;
        c.refused = e.what(); // a lattice whose sites are no common equilibrium
    }
    if (!c.refused)
        for (const auto* b : accurate) c.overlap.push_back(overlap(*b, c, kernel, lattice, k_max));
    return c;
}

} // namespace

void run_stability_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    if (!study.stability) return;
    const std::size_t kernels = inputs.kernels.size();
    std::vector<StabilityCase> cases(inputs.lattices.size() * kernels);
    Progress progress("stability", cases.size());
    std::mutex progress_mutex;
    auto run_case = [&](std::size_t index) {
        cases[index] = stability_case(study, inputs, results, index / kernels, index % kernels);
        std::lock_guard lock(progress_mutex);
        progress.step(inputs.kernels[index % kernels].name() + " on " + inputs.lattices[index / kernels].name);
    };
    // One case per thread at a time, taken in turn: their costs differ by orders of magnitude.
    std::atomic<std::size_t> next{0};
    ParallelFor pool;
    pool.run(cases.size(), worker_threads(0),
             [&](int, std::size_t, std::size_t) {
                 for (std::size_t i; pool.keep_going() && (i = next++) < cases.size();) run_case(i);
             });
    for (auto& c : cases) results.stability.push_back(std::move(c));
}

} // namespace sphkern
