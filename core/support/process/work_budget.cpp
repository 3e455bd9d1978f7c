#include "support/process/work_budget.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

std::string over_budget(const std::string& what, double amount, double limit, const std::string& how)
{
    if (!(amount > limit)) return {};
    // Whole numbers written out: "2000001, more than the limit of 2000000", never "2e+06 ... 2e+06".
    return fmt::format("asks for {} = {:.0f}, more than the limit of {:.0f}; make it smaller{}", what,
                       std::ceil(amount), limit, how.empty() ? "" : ": " + how);
}

void check_work_budget(const std::string& who, const std::string& what, double amount, double limit,
                       const std::string& how)
{
    if (auto refusal = over_budget(what, amount, limit, how); !refusal.empty()) fail_input(who + " " + refusal);
}

} // namespace sphkern
