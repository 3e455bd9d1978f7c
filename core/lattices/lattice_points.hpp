// Integer-indexed enumeration of the lattice points around one site: every point is
// basis * (n + motif_t - motif_s) for integer n, so no error accumulates.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace sphkern {

// The hard limit on points one request may enumerate.
inline constexpr std::size_t max_lattice_points = 5'000'000;

// Calls `visit(x)` for every lattice point x != 0 with |x| <= r_max around `site`.
// Throws Error(input) before enumerating if the request exceeds the limit.
void for_each_lattice_point(const Eigen::Matrix3d& basis, int dimension, const std::vector<Eigen::Vector3d>& motif,
                            int site, double r_max, const std::function<void(const Eigen::Vector3d&)>& visit);

// The same, telling which motif site each point belongs to: visit(x, t).
void for_each_lattice_point_of_site(const Eigen::Matrix3d& basis, int dimension,
                                    const std::vector<Eigen::Vector3d>& motif, int site, double r_max,
                                    const std::function<void(const Eigen::Vector3d&, int)>& visit);

// Pairwise Gauss reduction: the same lattice spanned by shorter, more orthogonal
// vectors. Returns the reduced basis and the unimodular M with reduced = basis M.
std::pair<Eigen::Matrix3d, Eigen::Matrix3d> reduce_basis(Eigen::Matrix3d basis, int dimension);

// An upper bound on the number of points within r_max of a site when the nearest
// neighbour distance is 1: disjoint balls of radius 1/2 fit in a ball of r_max + 1/2.
double lattice_point_bound(double r_max, int dimension);

} // namespace sphkern
