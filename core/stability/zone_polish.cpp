#include "stability/zone_polish.hpp"

#include "stability/zone_grid.hpp"

#include <boost/math/tools/minima.hpp>

#include <cmath>

namespace sphkern {

std::pair<Eigen::Vector3d, double> polish_minimum(const Dispersion& dispersion, const Eigen::Matrix3d& b,
                                                  Eigen::Vector3d f, double value, double reach,
                                                  double (*tolerance)(double), int rounds)
{
    for (int round = 0; round < rounds; ++round) {
        const double before = value;
        const Eigen::Vector3d start = f;
        std::tie(f, value) = refine_branch(dispersion, b, 0, f, value, reach, 1);
        const Eigen::Vector3d move = f - start;
        const double length = move.cwiseAbs().maxCoeff();
        if (length > 0) {
            // Along the move, as far again as it went on either side (at most `reach`).
            const Eigen::Vector3d u = move / length;
            const double span = std::min(reach, 2 * length);
            auto along = [&](double t) { return dispersion.omega2(b * (f + t * u)).front(); };
            std::uintmax_t iterations = 60;
            auto [t, ft] = boost::math::tools::brent_find_minima(along, -span, span, 30, iterations);
            if (ft < value) value = ft, f += t * u;
        }
        if (before - value <= tolerance(value)) break;
    }
    return {f, value};
}

} // namespace sphkern
