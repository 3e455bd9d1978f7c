// h^(D+2) d2W/dr2 of a kernel without its own formula, from its dW/dr: a sixth-order
// central difference (Boost.Math) away from breakpoints, a sixth-order one-sided
// difference on the side of q next to one. tests/unit/test_kernel_extensions.cpp checks it
// against W'' written by hand to 1e-8, on breakpoints too.
#pragma once

namespace sphkern {

class Kernel;

double numerical_second_derivative(const Kernel& kernel, double q, int dim, double k);

} // namespace sphkern
