// Integrals of a kernel over its support, piece by piece between its breakpoints (adaptive
// Gauss-Kronrod on each piece, so that no joint spoils the convergence).
#pragma once

#include "kernels/kernel.hpp"

#include <functional>
#include <utility>
#include <vector>

namespace sphkern {

// The area of the unit sphere in D dimensions: 2, 2 pi, 4 pi.
double sphere_area(int dim);

// 0, the kernel's breakpoints, R.
std::vector<double> piece_edges(const Kernel& kernel);

// The D-dimensional integral of a radial function f(q) over the support, and an error estimate.
std::pair<double, double> radial_integral(const Kernel& kernel, int dim, const std::function<double(double)>& f);

// ∫ W(q) q^radial_power d^D q over the support (1 for a normalised kernel), and an error estimate.
std::pair<double, double> kernel_integral(const Kernel& kernel, int dim, double k, int radial_power = 0);

// The integral of W over D-space by one 31-point Gauss-Kronrod rule per piece, not refined: exact
// for polynomial pieces, and enough where only its sign and finiteness matter (a kernel usable at
// a k). The adaptive rule's 1e-15 cannot be met where a piece's terms cancel (the quartic spline's
// three powers), and it then refines to its full depth at every k a scan evaluates.
double kernel_integral_estimate(const Kernel& kernel, int dim, double k);

} // namespace sphkern
