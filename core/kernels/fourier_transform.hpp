// The Fourier transform of a radial kernel truncated at R, by quadrature:
//   3D  4 pi  int_0^R w(q) q^2 sin(kh q)/(kh q) dq
//   2D  2 pi  int_0^R w(q) q J0(kh q) dq
//   1D  2     int_0^R w(q) cos(kh q) dq
// with w = h^D W, so the result is a function of kh = kappa h, 1 at kh = 0 for a
// normalised kernel. Adaptive Gauss-Kronrod on pieces between breakpoints, each piece
// cut into parts shorter than half an oscillation.
#pragma once

#include <functional>
#include <vector>

namespace sphkern {

class Kernel;

double fourier_transform_by_quadrature(const Kernel& kernel, double kh, int dim, double k);

// The radial transform of any profile f(q) on [0, R] with the given interior cuts.
double radial_fourier_transform(const std::function<double(double)>& f, double support, const std::vector<double>& cuts,
                                double kh, int dim);

} // namespace sphkern
