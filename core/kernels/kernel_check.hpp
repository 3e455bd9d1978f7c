// The kernel author's check-up: normalisation, derivative consistency, continuity at
// breakpoints and at R, moments, negative lobes and finiteness, in every dimension.
#pragma once

#include "kernels/kernel.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// Normalisation thresholds on |integral - 1|.
inline constexpr double normalization_ok = 1e-9;
inline constexpr double normalization_warn = 1e-2;       // a truncation loss above this fails
inline constexpr double normalization_truncation = 1e-6; // a constant off by more fails

// Runs every check in this process. The result has "kernel", "verdict" (ok, warn,
// fail), "normalization" ({"D": integral}), "second_moment" and "checks".
nlohmann::json check_kernel(const Kernel& kernel);

// The same in a child process with a time bound: a crash or hang is an Error(plugin).
nlohmann::json check_kernel_isolated(const Kernel& kernel, double timeout_seconds);

} // namespace sphkern
