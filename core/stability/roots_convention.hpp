// A roots window in a code's convention (`sphkern roots --convention`, the Python module's
// roots): the best k of condition (22), its intervals and the recommended k, converted.
#pragma once

#include "analysis/acceptance.hpp"
#include "analysis/code_conventions.hpp"
#include "stability/recommended_k.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// {"name", "quantity", and "undefined" (why) or "best_k", "accurate" and, when one was
// found, "recommended" and "recommended_interval"}.
nlohmann::json roots_convention_json(const CodeConvention& convention, const Kernel& kernel, int dim, double a_p,
                                     const Acceptance& accurate, const RecommendedK& recommended);

} // namespace sphkern
