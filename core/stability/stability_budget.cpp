#include "stability/stability_budget.hpp"

#include "stability/zone_minimum.hpp"
#include "support/process/work_budget.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sphkern {

double stability_wave_vectors(int steps, int grid, int dimension)
{
    auto points = [&](int dim) { return std::pow(grid > 0 ? grid : zone_start_grid(dim), dim); };
    const double zone = dimension == 0 ? std::max(points(2), points(3)) : points(dimension);
    return (steps + 1.0) * zone;
}

void check_stability_budget(const char* who, int steps, int grid, int dimension, const std::string& how)
{
    check_work_budget(who, "k samples x wave vectors", stability_wave_vectors(steps, grid, dimension),
                      max_stability_points, how);
}

double dispersion_neighbours(const Kernel& kernel, const Lattice& lattice, double k)
{
    const int D = lattice.dimension;
    const double r = kernel.support() * k;
    const double ball = D == 1 ? 2 * r : D == 2 ? M_PI * r * r : 4 * M_PI / 3 * r * r * r;
    return lattice.sites() * ball / lattice.volume_per_site();
}

void check_dispersion_neighbours(const Kernel& kernel, const Lattice& lattice, double k)
{
    check_work_budget(fmt::format("stability at k = {}", k), "neighbours within the support",
                      dispersion_neighbours(kernel, lattice, k), max_dispersion_neighbours);
}

double stability_neighbour_terms(const Kernel& kernel, const Lattice& lattice, double k_min, double k_max, int steps,
                                 int grid)
{
    const double wave_vectors = stability_wave_vectors(0, grid, lattice.dimension);
    double neighbours = 0;
    for (int i = 0; i <= steps; ++i)
        neighbours += dispersion_neighbours(kernel, lattice, steps > 0 ? k_min + (k_max - k_min) * i / steps : k_min);
    return neighbours * wave_vectors;
}

void check_stability_work(const char* who, const Kernel& kernel, const Lattice& lattice, double k_min, double k_max,
                          int steps, int grid, const std::string& how)
{
    check_work_budget(who, "neighbours x wave vectors",
                      stability_neighbour_terms(kernel, lattice, k_min, k_max, steps, grid),
                      max_stability_neighbour_terms, how);
}

void check_dispersion_work(const char* who, const Kernel& kernel, const Lattice& lattice, double k, double wave_vectors,
                           const std::string& how)
{
    check_work_budget(who, "neighbours x wave vectors", dispersion_neighbours(kernel, lattice, k) * wave_vectors,
                      max_stability_neighbour_terms, how);
}

} // namespace sphkern
