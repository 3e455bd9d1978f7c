// Neighbour shells: the lattice points around a site grouped by distance.
#pragma once

#include "lattices/lattice.hpp"

#include <Eigen/Core>

#include <vector>

namespace sphkern {

// Points whose distances differ by at most this (in units of d) share a shell.
inline constexpr double shell_tolerance = 1e-9;

struct Shell {
    double radius = 0; // in units of d
    int count = 0;
    Eigen::Matrix3d moment;                          // sum over the shell of r_hat r_hat^T
    Eigen::Vector3d first = Eigen::Vector3d::Zero(); // sum over the shell of r_hat (zero at a centre of inversion)

    // sum (e . r_hat)^2 over the shell: what the pressure gradient along e needs.
    double directional_moment(const Eigen::Vector3d& e) const { return e.dot(moment * e); }
};

// All shells of `site` with radius <= r_max, in increasing radius. Throws Error(input)
// for a non-positive or non-finite radius, a bad site, or a request beyond the limit.
std::vector<Shell> lattice_shells(const Lattice& lattice, int site, double r_max);

// A shell as `shells` lists it: its radius, its count and the count up to it, and its moment
// along a direction e.
struct ShellRow {
    double radius = 0;
    int count = 0, cumulative = 0;
    double moment_along = 0; // sum (e . r_hat)^2
};
std::vector<ShellRow> shell_rows(const Lattice& lattice, int site, double r_max, const Eigen::Vector3d& e);

} // namespace sphkern
