// The one rule for how much work a request may ask for, on the command line and in a study:
// the product of its counts, bounded as a whole before any of it is done.
#pragma once

#include <string>

namespace sphkern {

// "asks for WHAT = AMOUNT, more than the limit of LIMIT; make it smaller", or empty if within;
// `how` names what makes it smaller ("...; make it smaller: a smaller --k or --grid").
std::string over_budget(const std::string& what, double amount, double limit, const std::string& how = "");

// Throws Error(input) (exit 3) with `who` and the message of over_budget, if over.
void check_work_budget(const std::string& who, const std::string& what, double amount, double limit,
                       const std::string& how = "");

} // namespace sphkern
