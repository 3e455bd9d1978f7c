#include "study/report_text.hpp"

#include <fmt/format.h>

namespace sphkern {

std::string intervals_text(const std::vector<KInterval>& intervals, const std::string& none)
{
    if (intervals.empty()) return none;
    std::string s;
    for (const auto& i : intervals) s += fmt::format("{}[{:.4f}, {:.4f}]", s.empty() ? "" : " ", i.from, i.to);
    return s;
}

std::string intervals_text(const Acceptance& a) { return intervals_text(a.intervals, "-"); }

} // namespace sphkern
