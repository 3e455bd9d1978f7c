#include "stability/k_change_bound.hpp"

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

KChangeRates::KChangeRates(const Kernel& kernel, const Lattice& lattice, const RateGrid& grid, double k, double gamma,
                           HModel h_model)
    : k_(k), eps_(1e-5 * k), lo_(kernel, lattice, k - eps_, gamma, h_model),
      hi_(kernel, lattice, k + eps_, gamma, h_model)
{
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const Eigen::Vector3d& kappa = grid.kappa(i);
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
