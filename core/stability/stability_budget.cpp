#include "stability/stability_budget.hpp"

#include "stability/zone_minimum.hpp"
#include "support/work_budget.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

double stability_wave_vectors(int steps, int grid, int dimension)
{
    auto points = [&](int dim) { return std::pow(grid > 0 ? grid : zone_start_grid(dim), dim); };
    const double zone = dimension == 0 ? std::max(points(2), points(3)) : points(dimension);
    return (steps + 1.0) * zone;
}

void check_stability_budget(const char* who, int steps, int grid, int dimension)
{
    check_work_budget(who, "k samples x wave vectors", stability_wave_vectors(steps, grid, dimension),
                      max_stability_points);
}

} // namespace sphkern
