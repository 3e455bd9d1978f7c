// The stability part of a roots window (`sphkern roots --stability` and the Python module's
// roots): the stable k, their overlap with condition (22) and one recommended k.
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/hydrostatic_errors.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/h_model.hpp"
#include "stability/recommended_k.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace sphkern {

struct RootsStabilityOptions {
    double gamma = 5.0 / 3.0, horizon = 100;
    int steps = 100;
    HModel h_model = HModel::fixed;
    int threads = 0; // of the scan over k (0: every core); the answers are the same on any number
};

struct RootsStability {
    nlohmann::json json;           // {"refused": why} for a lattice without a dispersion matrix
    std::vector<KInterval> stable; // at the horizon
    std::vector<KInterval> both;   // and condition (22)
    RecommendedK recommended;
    bool refused() const { return json.contains("refused"); }
};

// `accurate`: the intervals of condition (22) at every site; `errors` gives N_H.
RootsStability roots_stability(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                               const RootsStabilityOptions& options, const std::vector<KInterval>& accurate,
                               const HydrostaticErrors& errors);

} // namespace sphkern
