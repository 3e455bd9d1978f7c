#include "stability/dispersion_path.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

DispersionPath dispersion_along_path(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int points)
{
    const auto path = high_symmetry_path(reciprocal);
    double total = 0;
    for (std::size_t i = 1; i < path.size(); ++i) total += (path[i].kappa - path[i - 1].kappa).norm();
    DispersionPath result;
    double at = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        result.labels.push_back(path[i].label);
        result.label_positions.push_back(at);
        if (i + 1 == path.size()) break;
        const Eigen::Vector3d from = path[i].kappa, step = path[i + 1].kappa - from;
        const double length = step.norm();
        const int n = std::max(2, static_cast<int>(std::ceil(points * length / std::max(total, 1e-300))));
        // Each segment from its start; the last segment includes its end.
        const int last = i + 2 == path.size() ? n : n - 1;
        for (int j = 0; j <= last; ++j) {
            const double t = static_cast<double>(j) / n;
            result.position.push_back(at + t * length);
            result.omega2.push_back(dispersion.omega2(from + t * step));
        }
        at += length;
    }
    return result;
}

} // namespace sphkern
