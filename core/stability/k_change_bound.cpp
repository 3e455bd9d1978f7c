#include "stability/k_change_bound.hpp"

#include "stability/zone_minimum.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace sphkern {

namespace {

// The lowest eigenvalue of the long-wave limit matrix along n (one site).
double long_wave_lowest(const Dispersion& d, const Eigen::Vector3d& n)
{
    const int D = d.dimension();
    const Eigen::MatrixXd m = d.long_wave_matrix(n).topLeftCorner(D, D);
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues()[0];
}

OmegaRate from_pair(double low, double high, double eps)
{
    const double rate = std::abs(high - low) / (2 * eps);
    return {0.5 * (low + high), std::isfinite(rate) ? rate : INFINITY};
}

} // namespace

KChangeRates::KChangeRates(const Kernel& kernel, const Lattice& lattice, const ReciprocalLattice& reciprocal, double k,
                           double gamma, HModel h_model, int grid)
    : k_(k), eps_(1e-5 * k), lo_(kernel, lattice, k - eps_, gamma, h_model), hi_(kernel, lattice, k + eps_, gamma, h_model)
{
    const int D = lattice.dimension, n = grid > 0 ? grid : zone_start_grid(D);
    const int per[3] = {n, D > 1 ? n : 1, D > 2 ? n : 1};
    for (int i = 0; i < per[0]; ++i)
        for (int j = 0; j < per[1]; ++j)
            for (int l = 0; l < per[2]; ++l) {
                const Eigen::Vector3d f(-0.5 + double(i) / n, D > 1 ? -0.5 + double(j) / n : 0,
                                        D > 2 ? -0.5 + double(l) / n : 0);
                const Eigen::Vector3d kappa = fold_to_first_zone(reciprocal, reciprocal.vectors * f);
                if (kappa.norm() < 1e-12) continue;
                kappa_.push_back(kappa);
                grid_.push_back(at(kappa));
                if (lattice.sites() == 1)
                    long_wave_.push_back(from_pair(long_wave_lowest(lo_, kappa), long_wave_lowest(hi_, kappa), eps_));
            }
}

OmegaRate KChangeRates::at(const Eigen::Vector3d& kappa) const
{
    return from_pair(lo_.omega2(kappa).front(), hi_.omega2(kappa).front(), eps_);
}

} // namespace sphkern
