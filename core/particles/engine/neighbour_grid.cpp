#include "particles/engine/neighbour_grid.hpp"

#include "particles/engine/periodic_images.hpp"

#include "support/error.hpp"
#include "support/process/first_touch.hpp"
#include "support/process/parallel_for.hpp"

#include <Eigen/LU>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sphkern {

namespace {

// The periodic images near the box's faces, in particle order.
struct Ghosts {
    FirstTouchVector<double> x, y, z;
    FirstTouchVector<std::uint32_t> source;
    std::size_t size() const { return x.size(); }
};

// Block by block of particles, each block's images in a list of its own, the lists copied
// into place in block order, each block by a thread: the same points in the same order on
// any thread count (and any block size), and no thread copies them all. Blocks of 2048, so
// that a set of 10^5 particles keeps 16 threads busy.
Ghosts find_ghosts(const ParticleSet& set, double reach, int threads)
{
    constexpr std::size_t block_size = 2048;
    const PeriodicImages images(*set.box, set.dimension, reach);
    std::vector<Ghosts> blocks((set.size() + block_size - 1) / block_size);
    ParallelFor pass;
    pass.run_blocks(set.size(), block_size, threads, [&](std::size_t block, std::size_t begin, std::size_t end) {
        Ghosts& g = blocks[block];
        for (std::size_t i = begin; i < end; ++i)
            images.of(set.position(i), [&](double x, double y, double z) {
                g.x.push_back(x), g.y.push_back(y), g.z.push_back(z);
                g.source.push_back(static_cast<std::uint32_t>(i));
            });
    });
    std::vector<std::size_t> first(blocks.size() + 1, 0);
    for (std::size_t b = 0; b < blocks.size(); ++b) first[b + 1] = first[b] + blocks[b].size();
    Ghosts all;
    all.x.resize(first.back()), all.y.resize(first.back()), all.z.resize(first.back()), all.source.resize(first.back());
    ParallelFor copy;
    copy.run_blocks(blocks.size(), 1, threads, [&](std::size_t b, std::size_t, std::size_t) {
        const auto at = static_cast<std::ptrdiff_t>(first[b]);
        std::copy(blocks[b].x.begin(), blocks[b].x.end(), all.x.begin() + at);
        std::copy(blocks[b].y.begin(), blocks[b].y.end(), all.y.begin() + at);
        std::copy(blocks[b].z.begin(), blocks[b].z.end(), all.z.begin() + at);
        std::copy(blocks[b].source.begin(), blocks[b].source.end(), all.source.begin() + at);
        blocks[b] = {};
    });
    return all;
}

// The points of a window's rows: its particles in set order, then the ghosts in theirs (the
// order they have among the whole set's points), each tagged as the grid stores it.
struct WindowPoints {
    std::vector<double> x, y, z;
    std::vector<std::uint32_t> tagged;
};

} // namespace

// The points before sorting: the particles, then their ghosts; or a window's points, tagged.
struct NeighbourGrid::Unsorted {
    const double* own[3];
    const double* image[3];
    const std::uint32_t* image_source;
    std::size_t particles;
    const std::uint32_t* tagged = nullptr; // a window's: source and unvisited bit of every point
    double at(int axis, std::size_t p) const { return p < particles ? own[axis][p] : image[axis][p - particles]; }
    std::uint32_t source(std::size_t p) const
    {
        return p < particles ? static_cast<std::uint32_t>(p) : image_source[p - particles];
    }
};

GridGeometry GridGeometry::of(const std::array<double, 6>& range, std::size_t count, double reach)
{
    GridGeometry g;
    double extent[3];
    for (int a = 0; a < 3; ++a) {
        extent[a] = range[2 * a + 1] - range[2 * a];
        g.lo[a] = range[2 * a];
        // Bins at least reach / stencil_reach wide (a quarter of that along x), so that the
        // block of bins around a bin holds every neighbour (wider bins are never wrong).
        const double per_reach =
            static_cast<double>(NeighbourGrid::stencil_reach * (a == 0 ? NeighbourGrid::x_bins_per_reach : 1));
        g.n[a] = static_cast<std::size_t>(std::clamp(std::floor(extent[a] / reach * per_reach), 1.0, 1e9));
    }
    // Not many more bins than points, so that sparse or long thin sets stay small: the axis
    // with the most bins is halved until they are few enough; and fewer than 2^32 bins in all,
    // so that a row or a bin along x is a 32-bit number.
    const double most = std::min(4 * static_cast<double>(count) + 64, 4294967295.0);
    while (static_cast<double>(g.n[0]) * static_cast<double>(g.n[1]) * static_cast<double>(g.n[2]) > most) {
        std::size_t& widest = *std::max_element(g.n, g.n + 3);
        widest = (widest + 1) / 2;
    }
    for (int a = 0; a < 3; ++a) g.scale[a] = extent[a] > 0 ? static_cast<double>(g.n[a]) / extent[a] : 0.0;
    return g;
}

NeighbourGrid::NeighbourGrid(const ParticleSet& set, double reach, int threads, const GridWindow* window)
    // A thread for every 4096 particles at most: on a small set, waking threads costs more than they save.
    : threads_(static_cast<int>(
          std::clamp<std::size_t>(set.size() / 4096 + 1, 1, static_cast<std::size_t>(std::max(1, threads))))),
      ids_(set.ids)
{
    if (!std::isfinite(reach) || reach <= 0)
        fail_input(fmt::format("{}: the support radius {} is not positive", set.name, reach));
    if (set.size() >= std::numeric_limits<std::uint32_t>::max() / 2)
        fail_input(fmt::format("{}: {} particles, more than this engine indexes", set.name, set.size()));
    particles_ = set.size();
    measured_ = set.measured();
    Ghosts ghosts;
    if (set.box) {
        const double width = set.box->smallest_width(set.dimension);
        if (width < 2 * reach)
            fail_input(fmt::format("{}: the periodic box is {:.6g} wide, less than twice the support radius {:.6g}; "
                                   "expected a larger box or a smaller h",
                                   set.name, width, reach));
        ghosts = find_ghosts(set, reach, threads_);
        // The sort numbers points (particles and ghosts) in 32 bits.
        if (particles_ + ghosts.size() >= std::numeric_limits<std::uint32_t>::max())
            fail_input(fmt::format("{}: {} particles and their periodic images, more than this engine indexes",
                                   set.name, particles_ + ghosts.size()));
    }
    const Unsorted all{{set.x.data(), set.y.data(), set.z.data()},
                       {ghosts.x.data(), ghosts.y.data(), ghosts.z.data()},
                       ghosts.source.data(),
                       particles_};
    if (!window) {
        size_bins(all, particles_ + ghosts.size(), reach);
        sort_into_bins(all, particles_ + ghosts.size());
        return;
    }
    // A slab: the whole set's bins, the window's rows kept.
    const int axis = window->axis;
    geometry_ = window->whole;
    std::copy(geometry_.n, geometry_.n + 3, n_);
    offset_[axis] = window->first, n_[axis] = window->last - window->first;
    WindowPoints kept;
    for (std::size_t p = 0; p < particles_ + ghosts.size(); ++p) {
        const std::size_t row = geometry_.bin(axis, all.at(axis, p));
        if (row < window->first || row >= window->last) continue;
        const bool visited = p < measured_ && row >= window->own_first && row < window->own_last;
        kept.x.push_back(all.at(0, p)), kept.y.push_back(all.at(1, p)), kept.z.push_back(all.at(2, p));
        kept.tagged.push_back(all.source(p) | (visited ? 0u : unvisited_bit));
    }
    ghosts = {};
    Unsorted points{{kept.x.data(), kept.y.data(), kept.z.data()}, {nullptr, nullptr, nullptr}, nullptr, kept.x.size()};
    points.tagged = kept.tagged.data();
    sort_into_bins(points, kept.x.size());
}

void NeighbourGrid::size_bins(const Unsorted& points, std::size_t count, double reach)
{
    // The extent along each axis: minima and maxima, exact in any order.
    using Range = std::array<double, 6>; // min and max along x, y, z
    const Range none = {INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY};
    const Range range = parallel_reduce(
        count, threads_, none,
        [&](std::size_t p, Range& r) {
            for (int a = 0; a < 3; ++a) {
                const double c = points.at(a, p);
                r[2 * a] = std::min(r[2 * a], c), r[2 * a + 1] = std::max(r[2 * a + 1], c);
            }
        },
        [](Range& r, const Range& block) {
            for (int a = 0; a < 3; ++a)
                r[2 * a] = std::min(r[2 * a], block[2 * a]), r[2 * a + 1] = std::max(r[2 * a + 1], block[2 * a + 1]);
        });
    geometry_ = GridGeometry::of(range, count, reach);
    std::copy(geometry_.n, geometry_.n + 3, n_);
}
// A stable counting sort by bin in two steps, first by row of bins (y and z), then by bin
// along x within each row: every step's counters stay in cache, where one pass over all the
// bins' counters (megabytes on a large set) missed it at every point. The first step carries
// the points themselves into the grid's arrays in row order (read in order, written to one
// stream per row); the second sorts each row in place through a buffer of one row, reading
// memory in order (carrying indices instead left it a cache miss per coordinate). A stable
// sort has one result, so the threads' shares (contiguous runs of points, rows) do not change
// it. Each array is allocated once and first touched by the threads that fill it.
void NeighbourGrid::sort_into_bins(const Unsorted& points, std::size_t count)
{
    const std::size_t rows = n_[1] * n_[2];
    // Each thread counts its run of points per row; fewer threads where the rows outnumber the points.
    const int counting =
        static_cast<int>(std::clamp<std::size_t>(count / (rows + 1), 1, static_cast<std::size_t>(threads_)));
    FirstTouchVector<std::uint32_t> row(count);
    std::vector<std::vector<std::uint32_t>> counts(static_cast<std::size_t>(counting));
    ParallelFor count_rows;
    count_rows.run(count, counting, [&](int t, std::size_t begin, std::size_t end) {
        auto& c = counts[static_cast<std::size_t>(t)];
        c.assign(rows, 0);
        for (std::size_t p = begin; p < end; ++p) {
            row[p] = static_cast<std::uint32_t>(bin_along(2, points.at(2, p)) * n_[1] + bin_along(1, points.at(1, p)));
            ++c[row[p]];
        }
    });
    // Thread t's first place in row r: the row's start and the earlier threads' points in it.
    std::vector<std::uint32_t> row_start(rows + 1, 0);
    for (std::size_t r = 0, at = 0; r < rows; ++r) {
        row_start[r] = static_cast<std::uint32_t>(at);
        for (auto& c : counts) {
            const std::uint32_t mine = c[r];
            c[r] = static_cast<std::uint32_t>(at), at += mine;
        }
    }
    row_start[rows] = static_cast<std::uint32_t>(count);
    x_.resize(count), y_.resize(count), z_.resize(count), source_.resize(count);
    ParallelFor place;
    place.run(count, counting, [&](int t, std::size_t begin, std::size_t end) {
        auto& next = counts[static_cast<std::size_t>(t)];
        for (std::size_t p = begin; p < end; ++p) {
            const std::uint32_t k = next[row[p]]++;
            x_[k] = points.at(0, p), y_[k] = points.at(1, p), z_[k] = points.at(2, p);
            // Ghosts follow the particles, and the neighbours-only particles end the particles.
            source_[k] = points.tagged ? points.tagged[p] : points.source(p) | (p >= measured_ ? unvisited_bit : 0u);
        }
    });
    row = {};
    sort_rows(row_start);
}

// Row by row: the bins along x counted, then each point written from the row's copy to its place.
void NeighbourGrid::sort_rows(const std::vector<std::uint32_t>& row_start)
{
    const std::size_t rows = row_start.size() - 1;
    start_.resize(rows * n_[0] + 1);
    ParallelFor within_rows;
    within_rows.run(rows, threads_, [&](int, std::size_t first_row, std::size_t last_row) {
        std::vector<std::uint32_t> fill(n_[0] + 1);
        std::vector<double> bx, by, bz;
        std::vector<std::uint32_t> bs;
        for (std::size_t r = first_row; r < last_row; ++r) {
            const std::uint32_t from = row_start[r], to = row_start[r + 1];
            bx.assign(x_.begin() + from, x_.begin() + to), by.assign(y_.begin() + from, y_.begin() + to);
            bz.assign(z_.begin() + from, z_.begin() + to), bs.assign(source_.begin() + from, source_.begin() + to);
            std::fill(fill.begin(), fill.end(), 0);
            for (double x : bx) ++fill[bin_along(0, x) + 1];
            fill[0] = from;
            for (std::size_t b = 0; b < n_[0]; ++b) fill[b + 1] += fill[b];
            std::copy(fill.begin(), fill.end() - 1, start_.begin() + static_cast<std::ptrdiff_t>(r * n_[0]));
            for (std::size_t k = 0; k < bx.size(); ++k) {
                const std::uint32_t q = fill[bin_along(0, bx[k])]++;
                x_[q] = bx[k], y_[q] = by[k], z_[q] = bz[k], source_[q] = bs[k];
            }
        }
    });
    start_.back() = row_start.back();
}

std::vector<double> NeighbourGrid::gather(std::span<const double> per_particle) const
{
    std::vector<double> values(x_.size());
    ParallelFor pass;
    pass.run(x_.size(), threads_, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) values[p] = per_particle[source(p)];
    });
    return values;
}

} // namespace sphkern
