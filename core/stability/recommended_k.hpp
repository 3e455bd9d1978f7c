// One recommended k: the centre of the widest interval where condition (22) holds and the
// lattice is stable at the horizon, with its margin (half the width) in k and the numbers of
// neighbours N_H across it; flagged when that interval touches the window, where it may go on.
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/hydrostatic_errors.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace sphkern {

struct RecommendedK {
    bool found = false;
    KInterval widest{0, 0};
    double k = 0, margin = 0;                   // centre and half width
    int neighbours = 0;                         // N_H at k
    int neighbours_from = 0, neighbours_to = 0; // at the ends of the interval
    bool at_window_edge = false;
};

// `both`: the intervals of condition (22) and stability; `errors` gives N_H.
RecommendedK recommend_k(const std::vector<KInterval>& both, double window_min, double window_max,
                         const HydrostaticErrors& errors);

nlohmann::json recommended_json(const RecommendedK& r);
std::string recommended_text(const RecommendedK& r);

} // namespace sphkern
