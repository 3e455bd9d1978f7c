#include "stability/zone_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>

namespace sphkern {

namespace {

// The D x D integer matrices with entries -1, 0, 1 (the rest of the 3 x 3 the identity) that
// keep the reciprocal lattice's metric B^T B: its orthogonal maps in that basis. They depend
// only on the basis, so they are found once per basis (3^9 candidates in 3D) and kept.
std::vector<Eigen::Matrix3i> orthogonal_maps(const Eigen::Matrix3d& full, int D)
{
    static std::mutex mutex;
    static std::vector<std::pair<Eigen::Matrix3d, std::vector<Eigen::Matrix3i>>> known;
    std::lock_guard lock(mutex);
    for (const auto& [basis, maps] : known)
        if (basis == full) return maps;
    const Eigen::Matrix3d metric = full.transpose() * full;
    std::vector<Eigen::Matrix3i> maps;
    int count = 1;
    for (int i = 0; i < D * D; ++i) count *= 3;
    for (int code = 0; code < count; ++code) {
        Eigen::Matrix3i n = Eigen::Matrix3i::Identity();
        int c = code;
        for (int i = 0; i < D * D; ++i, c /= 3) n(i / D, i % D) = c % 3 - 1;
        const Eigen::Matrix3d m = n.cast<double>();
        if ((m.transpose() * metric * m - metric).norm() <= 1e-9 * metric.norm()) maps.push_back(n);
    }
    known.emplace_back(full, maps);
    return maps;
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
    for (const auto& n : orthogonal_maps(full, D)) {
        if (n == Eigen::Matrix3i::Identity()) continue;
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
