// The resolution scale a window is given in. k = h / d depends on the lattice's d;
// h_over_l = h / V^(1/D) (Axis::eta), sphkern's h over the mean spacing with V = a_p d^D the
// particle volume, is comparable across lattices and volume coefficients; nh is the number of neighbours
// inside the support R h (a step function of k, counted at a site).
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"

#include <string>
#include <utility>

namespace sphkern {

enum class Axis { k, eta, nh };

Axis parse_axis(const std::string& text, const std::string& what); // "k", "h_over_l" or "nh"; Error(input) otherwise
const char* axis_name(Axis axis);

// eta = k / a_p^(1/D), and back.
double eta_of_k(double k, double a_p, int dimension);
double k_of_eta(double eta, double a_p, int dimension);

// The k interval a window [lo, hi] on `axis` stands for, at `site` for nh: the smallest k
// with at least lo neighbours inside the support, to the largest with at most hi.
// Throws Error(input) naming `what` if the window is empty or out of reach.
std::pair<double, double> k_window(Axis axis, double lo, double hi, const Kernel& kernel, const Lattice& lattice,
                                   int site, double a_p, const std::string& what);

} // namespace sphkern
