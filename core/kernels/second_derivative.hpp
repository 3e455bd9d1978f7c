// h^(D+2) d2W/dr2 of a kernel without its own formula, from its dW/dr: a sixth-order
// central difference (Boost.Math) away from breakpoints, a sixth-order one-sided
// difference on the side of q next to one. Relative accuracy about 1e-11 on the
// shipped kernels (tests/unit/test_second_derivative.cpp).
#pragma once

namespace sphkern {

class Kernel;

double numerical_second_derivative(const Kernel& kernel, double q, int dim, double k);

} // namespace sphkern
