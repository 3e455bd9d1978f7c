// Whether a verdict found at both ends of a cell of k must hold across it (the method
// document, "Over k"). Two rules: strict (no mode grows) and the horizon (no mode grows
// faster than the growth-time horizon T). At each wave vector kappa of the first zone grid,
// at the refined minima of both ends and, for the strict rule, along the long-wave directions,
// omega^2 changes with k no faster than R(kappa), the largest rate at the cell's ends and
// middle times k_change_safety. Then, with t the rule's threshold and w the cell's width:
//   it holds at both ends: every kappa has (omega2_a - t) + (omega2_b - t) >= R w, so omega^2
//     stays at or above t across the cell;
//   it fails at both ends: the farthest reach of an unstable kappa from each end,
//     max (t - omega2) / R, adds up to at least w.
#pragma once

#include "stability/k_change_bound.hpp"
#include "stability/stability_over_k.hpp"

namespace sphkern {

enum class StabilityRule { strict, horizon };

// Whether the sample passes the rule: stable (strict); not unstable at the horizon.
bool rule_holds(const StabilitySample& s, StabilityRule rule);

// The rates at a cell's ends and middle.
struct CellRates {
    const KChangeRates& a;
    const KChangeRates& middle;
    const KChangeRates& b;
};

// `a` and `b` agree under the rule; whether no change of verdict can lie between them.
bool verdict_spans(StabilityRule rule, const StabilitySample& a, const StabilitySample& b, const CellRates& rates,
                   double horizon);

} // namespace sphkern
