#include "stability/roots_stability.hpp"

#include "analysis/results_json.hpp"
#include "stability/stability_over_k.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

namespace sphkern {

RootsStability roots_stability(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                               const RootsStabilityOptions& options, const std::vector<KInterval>& accurate,
                               const HydrostaticErrors& errors)
{
    RootsStability r;
    const std::string model = h_model_name(options.h_model);
    try {
        const auto scan = stability_over_k(kernel, lattice, k_min, k_max, options.steps, options.gamma, 0,
                                           worker_threads(options.threads), options.horizon, options.h_model);
        r.stable = scan.usable;
        r.both = accurate_and_stable(accurate, scan);
        r.json = {{"gamma", options.gamma},
                  {"h_model", model},
                  {"horizon", options.horizon},
                  {"stable_intervals", intervals_json(scan.stable)},
                  {"stable_at_horizon", intervals_json(scan.usable)},
                  {"accurate_and_stable", intervals_json(r.both)}};
        r.recommended = recommend_k(r.both, k_min, k_max, errors);
        r.json["recommended"] = recommended_json(r.recommended);
    } catch (const Error& e) {
        if (e.code() != ExitCode::input) throw;
        r = {};
        r.json = {{"gamma", options.gamma}, {"h_model", model}, {"refused", e.what()}};
    }
    return r;
}

} // namespace sphkern
