// omega^2 of every branch on an n^D grid over the reciprocal cell (fractions -1/2 + i/n on
// each axis, so that Γ and the zone boundary are on it), evaluated once per orbit of the
// spectrum's symmetries and filled in by them; the grid's valleys; local refinement.
#pragma once

#include "stability/dispersion.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <utility>
#include <vector>

namespace sphkern {

class ZoneGrid {
public:
    ZoneGrid(const Dispersion& dispersion, const Eigen::Matrix3d& reciprocal_vectors, int n,
             const std::vector<Eigen::Matrix3i>& symmetries, int threads);

    int per_axis() const { return n_; }
    std::size_t size() const { return lowest_.size(); }
    std::size_t evaluated() const { return evaluated_; } // points evaluated: one per orbit
    Eigen::Vector3d fraction(std::size_t index) const;
    std::size_t gamma_index() const;
    double lowest(std::size_t index) const { return lowest_[index]; }
    // The grid minimum of a branch and where it is.
    std::pair<double, std::size_t> branch_minimum(int branch) const;
    // The grid's local minima of the lowest branch (periodic neighbours, ties allowed) other
    // than Γ, lowest first, one per value (symmetric copies once), at most `count`.
    std::vector<std::size_t> valleys(int count) const;

private:
    int n_, D_;
    std::vector<double> lowest_;          // the lowest branch at every point
    std::vector<double> minimum_;         // per branch: the grid minimum
    std::vector<std::size_t> minimum_at_; // and where it is
    std::size_t evaluated_ = 0;
};

// Coordinate-wise Brent minimisation of one branch from fractions f, within `reach` on each
// axis, `sweeps` times over the axes; returns the fractions and the value found.
std::pair<Eigen::Vector3d, double> refine_branch(const Dispersion& dispersion,
                                                 const Eigen::Matrix3d& reciprocal_vectors, int branch,
                                                 Eigen::Vector3d f, double value, double reach, int sweeps);

} // namespace sphkern
