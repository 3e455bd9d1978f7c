// The consistency error e0 of a uniform random (Poisson) set, the reference a relaxed or
// disordered set is judged against (share/docs/method.md section 11):
//   E[e0] = V W(0) - 1/N,   Var[e0] = (N - 1) (V ∫W² / N - 1/N²),
// with V ∫W² = ∫ w(q)² d^D q / eta^D for h = eta V^(1/D).
#pragma once

#include "kernels/kernel.hpp"

#include <cstddef>

namespace sphkern {

// ∫ w(q)^2 d^D q over the support.
double kernel_square_integral(const Kernel& kernel, int dim, double k);

// The RMS of e0 over a Poisson set of n particles at h = eta V^(1/D): sqrt(Var + mean^2).
double poisson_rms_e0(const Kernel& kernel, int dim, double k, double eta, std::size_t n);

} // namespace sphkern
