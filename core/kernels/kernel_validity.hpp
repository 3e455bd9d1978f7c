// A kernel may be valid at its default parameters and not at others (a sign flip, a
// pole), or non-finite on a narrow band of q that a probe misses. These checks run
// where a kernel is used, so that no wrong number is printed as a result.
#pragma once

#include "kernels/kernel.hpp"
#include "support/error.hpp"

#include <span>

namespace sphkern {

// Plugins' faults are plugin errors (4); an expression file's are input errors (3).
ExitCode kernel_fault_code(const Kernel& kernel);

// Throws unless the kernel's integral over D-space at these parameters and k is finite
// and positive.
void require_usable_kernel(const Kernel& kernel, int dim, double k);

// Names the kernel, its parameters, q and k: `what` is "W" or "dW/dr".
[[noreturn]] void fail_non_finite_kernel(const Kernel& kernel, const char* what, double q, int dim, double k);

// A sum of kernel values (`sum`: "the density sum") overflowed while every value in it is finite:
// where W or dW/dr is far from order 1 (above 1e100) at the sum's q or on a sample of [0, R],
// the kernel's fault, naming the band of q where it is that large (Error with its fault code);
// else nothing.
void fail_overflowing_kernel(const Kernel& kernel, int dim, double k, const std::string& sum,
                             std::span<const double> q_values = {});

// A sum of kernel values came out non-finite at `where`: the kernel's fault if W or W' is
// non-finite at one of the sum's q (`neighbour_q`, where known) or on a sample of [0, R] at
// this k (Error with its fault code), else the scale's (k or h so small or large that the
// sum overflows: Error(input) naming `scale`).
[[noreturn]] void fail_non_finite_sum(const Kernel& kernel, int dim, double k, const std::string& where,
                                      const std::string& scale, std::span<const double> neighbour_q = {});

} // namespace sphkern
