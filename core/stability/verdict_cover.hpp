// The stable intervals over [k_min, k_max] to stability_k_tolerance, whatever the samples of
// a curve (the method document, "Over k"): the window is cut into cells of its own (at most
// cover_cell_width wide, and at the k where the dispersion matrix jumps); a cell is settled
// when, under each rule, the verdicts at its ends agree and their reaches (verdict_reach)
// cover it, and is halved otherwise, down to stability_k_tolerance. A change of verdict is
// the middle of the last cell across it.
#pragma once

#include "analysis/acceptance.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/h_model.hpp"
#include "stability/stability_over_k.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace sphkern {

inline constexpr double cover_cell_width = 1.0 / 32;
// Samples one cover may take; past them, a cell whose ends agree is no longer halved (a
// warning says the intervals are then not certain) while changes of verdict still are.
inline constexpr int cover_sample_limit = 20000;

struct VerdictCover {
    std::vector<StabilitySample> looked_at; // every k sampled, ascending
    std::vector<KInterval> stable;          // strict: no mode grows
    std::vector<KInterval> usable;          // no mode grows faster than the horizon
    bool certain = true;                    // every cell settled (the sample limit not reached)
};

struct CoverModel {
    double gamma = 5.0 / 3.0, horizon = default_horizon;
    HModel h_model = HModel::fixed;
    int grid = 0; // the first zone grid per axis (0: the default)
};

// The rates over k (k_change_bound.hpp) measured ahead of a cover, on one rate grid.
struct CoverRates;

// `at` gives the sample at k (the zone scan, as every mode computes it); `known` rates measured
// ahead, used where the cover's own rate grid is theirs (the same values it would measure).
VerdictCover cover_verdicts(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                            const CoverModel& model, const std::function<StabilitySample(double)>& at,
                            const CoverRates* known = nullptr);

// Asks `at`, on `threads` threads, for the samples cover_verdicts will most likely ask for, and
// measures the rates it will most likely need: every cell halved as the cover halves it, a round
// of halvings at a time, each round's samples and rates side by side. `at` must be safe to call
// from several threads and should keep what it finds; the cover that follows asks for what it
// needs in its own order, so its answer does not depend on what was taken here.
std::shared_ptr<const CoverRates> prefetch_cover(const Kernel& kernel, const Lattice& lattice, double k_min,
                                                 double k_max, const CoverModel& model,
                                                 const std::function<StabilitySample(double)>& at, int threads);

} // namespace sphkern
