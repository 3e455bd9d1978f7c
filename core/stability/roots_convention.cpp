#include "stability/roots_convention.hpp"

#include <nlohmann/json.hpp>


namespace sphkern {

nlohmann::json roots_convention_json(const CodeConvention& c, const Kernel& kernel, int dim, double a_p,
                                     const Acceptance& accurate, const RecommendedK& recommended)
{
    nlohmann::json conv = {{"name", c.name}, {"quantity", c.quantity}};
    if (const auto why = convention_undefined(c, kernel, dim); !why.empty()) {
        conv["undefined"] = why;
        return conv;
    }
    auto in = [&](double k) { return in_convention(c, kernel, dim, a_p, k); };
    nlohmann::json intervals = nlohmann::json::array();
    for (const auto& i : accurate.intervals) intervals.push_back({in(i.from), in(i.to)});
    conv.update({{"best_k", in(accurate.best_k)}, {"accurate", intervals}});
    if (recommended.found)
        conv.update({{"recommended", in(recommended.k)},
                     {"recommended_interval", {in(recommended.widest.from), in(recommended.widest.to)}}});
    return conv;
}

} // namespace sphkern
