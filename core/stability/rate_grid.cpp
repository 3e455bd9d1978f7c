#include "stability/rate_grid.hpp"

#include "stability/zone_minimum.hpp"
#include "stability/zone_symmetry.hpp"

#include <Eigen/LU>

namespace sphkern {

namespace {

// The first zone grid's wave vectors, folded, Γ left out, in grid order.
std::vector<Eigen::Vector3d> folded_grid(const ReciprocalLattice& reciprocal, int D, int grid)
{
    const int n = grid > 0 ? grid : zone_start_grid(D);
    const int per[3] = {n, D > 1 ? n : 1, D > 2 ? n : 1};
    std::vector<Eigen::Vector3d> all;
    for (int i = 0; i < per[0]; ++i)
        for (int j = 0; j < per[1]; ++j)
            for (int l = 0; l < per[2]; ++l) {
                const Eigen::Vector3d f(-0.5 + double(i) / n, D > 1 ? -0.5 + double(j) / n : 0,
                                        D > 2 ? -0.5 + double(l) / n : 0);
                const Eigen::Vector3d kappa = fold_to_first_zone(reciprocal, reciprocal.vectors * f);
                if (kappa.norm() >= 1e-12) all.push_back(kappa);
            }
    return all;
}

// The symmetries as Cartesian maps of wave vectors: B N B^-1.
std::vector<Eigen::Matrix3d> cartesian_maps(const std::vector<Eigen::Matrix3i>& symmetries,
                                            const ReciprocalLattice& reciprocal)
{
    Eigen::Matrix3d full = reciprocal.vectors;
    for (int a = reciprocal.dimension; a < 3; ++a) full.col(a) = Eigen::Vector3d::Unit(a);
    const Eigen::Matrix3d inverse = full.inverse();
    std::vector<Eigen::Matrix3d> maps;
    for (const auto& s : symmetries) maps.push_back(full * s.cast<double>() * inverse);
    return maps;
}

} // namespace

RateGrid::RateGrid(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int grid)
{
    const auto all = folded_grid(reciprocal, dispersion.dimension(), grid);
    const auto maps = cartesian_maps(zone_symmetries(dispersion, reciprocal), reciprocal);
    points_ = all.size();
    // A point is the image of an earlier orbit's wave vector under a symmetry, or a new orbit.
    for (const Eigen::Vector3d& kappa : all) {
        bool image = false;
        for (std::size_t r = 0; r < kappa_.size() && !image; ++r)
            for (const auto& m : maps)
                if ((m * kappa_[r] - kappa).norm() <= 1e-12 * kappa.norm()) {
                    image = true;
                    break;
                }
        if (!image) kappa_.push_back(kappa);
    }
}

} // namespace sphkern
