#include "stability/zone_symmetry.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

// Every D x D matrix with entries -1, 0, 1 (the rest of the 3 x 3 is the identity).
std::vector<Eigen::Matrix3i> candidates(int D)
{
    std::vector<Eigen::Matrix3i> all;
    int count = 1;
    for (int i = 0; i < D * D; ++i) count *= 3;
    for (int code = 0; code < count; ++code) {
        Eigen::Matrix3i n = Eigen::Matrix3i::Identity();
        int c = code;
        for (int i = 0; i < D * D; ++i, c /= 3) n(i / D, i % D) = c % 3 - 1;
        all.push_back(n);
    }
    return all;
}

bool same_spectrum(const std::vector<double>& a, const std::vector<double>& b)
{
    double scale = 1e-12;
    for (double x : a) scale = std::max(scale, std::abs(x));
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::abs(a[i] - b[i]) > 1e-9 * scale) return false;
    return true;
}

} // namespace

std::vector<Eigen::Matrix3i> zone_symmetries(const Dispersion& dispersion, const ReciprocalLattice& reciprocal)
{
    const int D = reciprocal.dimension;
    const Eigen::Matrix3d b = reciprocal.vectors;
    Eigen::Matrix3d full = b;
    for (int a = D; a < 3; ++a) full.col(a) = Eigen::Vector3d::Unit(a);
    const Eigen::Matrix3d to_fractions = full.inverse();
    // Two generic wave vectors (no symmetry maps one onto itself), away from long waves.
    const std::vector<Eigen::Vector3d> probes{Eigen::Vector3d(0.1234, 0.2718, 0.3141),
                                              Eigen::Vector3d(0.3770, -0.1610, 0.0917)};
    std::vector<std::vector<double>> reference;
    for (const auto& f : probes) {
        Eigen::Vector3d g = f;
        g.tail(3 - D).setZero();
        reference.push_back(dispersion.omega2(full * g));
    }
    std::vector<Eigen::Matrix3i> found{Eigen::Matrix3i::Identity()};
    for (const auto& n : candidates(D)) {
        if (n == Eigen::Matrix3i::Identity()) continue;
        const Eigen::Matrix3d r = full * n.cast<double>() * to_fractions; // Cartesian
        if (!(r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-9)) continue;
        bool keeps = true;
        for (std::size_t p = 0; p < probes.size() && keeps; ++p) {
            Eigen::Vector3d g = probes[p];
            g.tail(3 - D).setZero();
            keeps = same_spectrum(reference[p], dispersion.omega2(full * (n.cast<double>() * g)));
        }
        if (keeps) found.push_back(n);
    }
    return found;
}

} // namespace sphkern
