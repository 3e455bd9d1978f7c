#include "lattices/lattice_points.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/process/work_budget.hpp"

#include <Eigen/LU>
#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace sphkern {

double lattice_point_bound(double r_max, int dimension) { return std::pow(2.0 * r_max + 1.0, dimension); }

// Pairwise Gauss reduction: the same lattice spanned by shorter, more orthogonal
// vectors, so that the box searched around a point stays small however skewed the
// given basis is. Returns the reduced basis and the unimodular M with reduced = basis M.
std::pair<Eigen::Matrix3d, Eigen::Matrix3d> reduce_basis(Eigen::Matrix3d basis, int dimension)
{
    Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
    for (int sweep = 0; sweep < 200; ++sweep) {
        bool changed = false;
        for (int i = 0; i < dimension; ++i)
            for (int j = 0; j < dimension; ++j) {
                if (i == j) continue;
                double mu = std::round(basis.col(i).dot(basis.col(j)) / basis.col(j).squaredNorm());
                if (mu == 0 || !std::isfinite(mu)) continue;
                basis.col(i) -= mu * basis.col(j);
                m.col(i) -= mu * m.col(j);
                changed = true;
            }
        if (!changed) break;
    }
    return {basis, m};
}

void for_each_lattice_point(const Eigen::Matrix3d& basis, int dimension, const std::vector<Eigen::Vector3d>& motif,
                            int site, double r_max, const std::function<void(const Eigen::Vector3d&)>& visit)
{
    for_each_lattice_point_of_site(basis, dimension, motif, site, r_max,
                                   [&](const Eigen::Vector3d& x, int) { visit(x); });
}

void for_each_lattice_point_of_site(const Eigen::Matrix3d& basis, int dimension,
                                    const std::vector<Eigen::Vector3d>& motif, int site, double r_max,
                                    const std::function<void(const Eigen::Vector3d&, int)>& visit)
{
    // |n_i| <= |row_i(reduced^-1)| r_max + 1 bounds the box that can hold points within r_max.
    const auto [reduced, change] = reduce_basis(basis, dimension);
    const Eigen::Matrix3d to_reduced = change.inverse(); // fractional coordinates in the reduced basis
    Eigen::Matrix3d inverse = reduced.inverse();
    long long extent[3] = {0, 0, 0};
    double box = 1;
    for (int i = 0; i < dimension; ++i) {
        double e = std::ceil(inverse.row(i).norm() * r_max) + 1;
        if (e > 1e6) e = 1e6;
        extent[i] = static_cast<long long>(e);
        box *= 2.0 * e + 1;
    }
    box *= static_cast<double>(motif.size());
    // Too large a radius, or too skewed a basis.
    check_work_budget(fmt::format("radius {}", r_max), "cells to search", box, 50.0 * max_lattice_points);
    const double r2 = r_max * r_max * (1 + 1e-12);
    const Eigen::Vector3d& origin = motif[static_cast<std::size_t>(site)];
    for (std::size_t t = 0; t < motif.size(); ++t) {
        Eigen::Vector3d offset = to_reduced * (motif[t] - origin);
        for (int i = 0; i < dimension; ++i) offset[i] -= std::round(offset[i]); // nearest image of the site
        for (long long a = -extent[0]; a <= extent[0]; ++a) {
            throw_if_interrupted();
            for (long long b = -extent[1]; b <= extent[1]; ++b)
                for (long long c = -extent[2]; c <= extent[2]; ++c) {
                    Eigen::Vector3d f(double(a) + offset.x(), double(b) + offset.y(), double(c) + offset.z());
                    Eigen::Vector3d x = reduced * f;
                    double d2 = x.squaredNorm();
                    if (d2 > r2 || d2 < 1e-18) continue;
                    visit(x, static_cast<int>(t));
                }
        }
    }
}

} // namespace sphkern
