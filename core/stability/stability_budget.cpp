#include "stability/stability_budget.hpp"

#include "support/work_budget.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

double stability_wave_vectors(int steps, int grid, int dimension)
{
    auto points = [&](int dim) { return grid > 0 ? std::pow(grid, dim) : dim == 3 ? 8.0 * 8 * 8 : 32.0 * 32; };
    const double zone = dimension == 0 ? std::max(points(2), points(3)) : points(dimension);
    return (steps + 1.0) * zone;
}

void check_stability_budget(const char* who, int steps, int grid, int dimension)
{
    check_work_budget(who, "k samples x wave vectors", stability_wave_vectors(steps, grid, dimension),
                      max_stability_points);
}

} // namespace sphkern
