#include "particles/neighbour_gather.hpp"

#include "support/error.hpp"

#include <sphkern/kernel_plugin_helpers.h> // SPHKERN_VECTOR_CLONES

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sphkern {

void Neighbours::reserve(std::size_t n)
{
    if (dx.size() >= n) return;
    const std::size_t size = std::max(n, 2 * dx.size());
    for (auto* v : {&r2, &dx, &dy, &dz, &r, &q, &a, &b, &w, &dw}) v->resize(size);
    index.resize(size);
}

void runs_of_bin(const NeighbourGrid& grid, std::size_t b, std::vector<PointRun>& runs)
{
    runs.clear();
    grid.for_each_run_of_bin(b, [&](std::size_t first, std::size_t last) {
        if (last > first) runs.push_back({first, last});
    });
}

namespace {

// r2 of every point of a run: no branch, so that it vectorises.
SPHKERN_VECTOR_CLONES void squared_distances(const double* __restrict x, const double* __restrict y,
                                             const double* __restrict z, std::size_t n, double xi, double yi, double zi,
                                             double* __restrict r2)
{
    for (std::size_t c = 0; c < n; ++c) {
        const double dx = x[c] - xi, dy = y[c] - yi, dz = z[c] - zi;
        r2[c] = dx * dx + dy * dy + dz * dz;
    }
}

// Appends the points first + c of a run with r2[c] <= reach2 to `index` (one comparison, no branch).
std::size_t append_inside(const double* __restrict r2, std::size_t n, double reach2, std::uint32_t first,
                          std::uint32_t* __restrict index)
{
    std::size_t m = 0;
    for (std::size_t c = 0; c < n; ++c) {
        index[m] = first + static_cast<std::uint32_t>(c);
        m += r2[c] <= reach2;
    }
    return m;
}

// The neighbours' displacements, distances and values, gathered by index.
SPHKERN_VECTOR_CLONES void gather_by_index(const double* __restrict x, const double* __restrict y,
                                           const double* __restrict z, const double* __restrict a,
                                           const double* __restrict b, const std::uint32_t* __restrict index,
                                           std::size_t n, double xi, double yi, double zi, double* __restrict dx,
                                           double* __restrict dy, double* __restrict dz, double* __restrict r,
                                           double* __restrict va, double* __restrict vb)
{
    for (std::size_t j = 0; j < n; ++j) {
        const std::uint32_t s = index[j];
        dx[j] = x[s] - xi, dy[j] = y[s] - yi, dz[j] = z[s] - zi;
        r[j] = std::sqrt(dx[j] * dx[j] + dy[j] * dy[j] + dz[j] * dz[j]);
        va[j] = a[s], vb[j] = b[s];
    }
}

} // namespace

void gather_neighbours(const NeighbourGrid& grid, std::size_t p, const std::vector<PointRun>& runs, double reach2,
                       const double* a, const double* b, const std::string& set_name, Neighbours& nb)
{
    const double xi = grid.x()[p], yi = grid.y()[p], zi = grid.z()[p];
    std::size_t m = 0;
    for (const auto& run : runs) {
        const std::size_t n = run.end - run.begin;
        nb.reserve(m + n);
        squared_distances(grid.x() + run.begin, grid.y() + run.begin, grid.z() + run.begin, n, xi, yi, zi, nb.r2.data());
        m += append_inside(nb.r2.data(), n, reach2, static_cast<std::uint32_t>(run.begin), nb.index.data() + m);
    }
    gather_by_index(grid.x(), grid.y(), grid.z(), a, b, nb.index.data(), m, xi, yi, zi, nb.dx.data(), nb.dy.data(),
                    nb.dz.data(), nb.r.data(), nb.a.data(), nb.b.data());
    // The point itself is the one neighbour at r = 0; another one there is a duplicate.
    std::size_t self = m;
    for (std::size_t j = 0; j < m; ++j)
        if (nb.r[j] == 0) {
            if (nb.index[j] != p) {
                const auto i = grid.source(p), k = grid.source(nb.index[j]);
                fail_input(fmt::format("{}: particles {} and {} are at the same position ({:g}, {:g}, {:g})", set_name,
                                       std::min(i, k), std::max(i, k), xi, yi, zi));
            }
            self = j;
        }
    if (self == m) throw std::logic_error("a particle is not among its own candidates");
    // Out of the list: the last neighbour takes its place.
    for (auto* v : {&nb.dx, &nb.dy, &nb.dz, &nb.r, &nb.a, &nb.b}) (*v)[self] = (*v)[m - 1];
    nb.index[self] = nb.index[m - 1];
    nb.count = m - 1;
}

SPHKERN_VECTOR_CLONES void scale_distances(const double* __restrict r, std::size_t n, double factor, double* __restrict q)
{
    for (std::size_t j = 0; j < n; ++j) q[j] = r[j] * factor;
}

} // namespace sphkern
