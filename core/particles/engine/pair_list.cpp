#include "particles/engine/pair_list.hpp"

#include "support/process/parallel_for.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sphkern {

namespace {

// The skin that fits: a periodic box holds twice the support and the skin (NeighbourGrid).
double fitting_skin(const ParticleSet& set, double support, double skin)
{
    if (!std::isfinite(skin) || skin <= 0) return 0;
    if (!set.box) return skin;
    return std::clamp(set.box->smallest_width(set.dimension) / 2 / (1 + 1e-9) - support, 0.0, skin);
}

} // namespace

PairList::PairList(const ParticleSet& set, double support, double skin, int threads)
    : support_(support), skin_(fitting_skin(set, support, skin)), threads_(threads)
{
    rebuild(set);
}

void PairList::rebuild(const ParticleSet& set)
{
    grid_.reset(), order_.reset(); // freed before the next is made
    grid_.emplace(set, support_ + skin_, threads_);
    order_.emplace(*grid_);
    colours_ = tiles_by_colour(*grid_);
    since_build_.emplace(set);
    set_name_ = set.name;
    x_.assign(grid_->x(), grid_->x() + grid_->points());
    y_.assign(grid_->y(), grid_->y() + grid_->points());
    z_.assign(grid_->z(), grid_->z() + grid_->points());
    build();
}

void PairList::build()
{
    const NeighbourGrid& grid = *grid_;
    const double list_reach = search_reach(support_) + skin_;
    std::vector<double> point_index(grid.points()); // gathered as the candidates' `a`: their points
    std::iota(point_index.begin(), point_index.end(), 0.0);
    std::vector<PairTile> tiles;
    for (const auto& tiles_of_colour : colours_)
        tiles.insert(tiles.end(), tiles_of_colour.begin(), tiles_of_colour.end());
    tile_lists_.resize(tiles.size());
    cluster_candidates_.assign(grid.clusters(), {});
    point_neighbours_.assign(grid.points(), {});
    std::vector<ClusterScratch> scratch(static_cast<std::size_t>(std::max(1, threads_)));
    ParallelFor pass;
    pass.run_blocks(tiles.size(), 1, threads_, [&](int thread, std::size_t t, std::size_t, std::size_t) {
        ClusterScratch& mine = scratch[static_cast<std::size_t>(thread)];
        TileList& list = tile_lists_[tiles[t].index];
        list.candidates.clear(), list.neighbours.clear(); // their room kept from the last build
        for (std::size_t c = tiles[t].begin; c < tiles[t].end; ++c) {
            gather_cluster(grid, c, {nullptr, list_reach}, point_index.data(), nullptr, mine.cluster, &*order_);
            cluster_candidates_[c] = {list.candidates.size(), list.candidates.size() + mine.cluster.count};
            for (std::size_t k = 0; k < mine.cluster.count; ++k)
                list.candidates.push_back(static_cast<std::uint32_t>(mine.cluster.a[k]));
            for (std::size_t p = grid.cluster_begin(c); mine.cluster.count > 0 && p < grid.cluster_end(c); ++p) {
                if (!grid.visited(p)) continue;
                gather_from_cluster(grid, mine.cluster, p, list_reach * list_reach, set_name_, mine.nb);
                point_neighbours_[p] = {list.neighbours.size(), list.neighbours.size() + mine.nb.count};
                for (std::size_t j = 0; j < mine.nb.count; ++j)
                    list.neighbours.push_back(static_cast<std::uint32_t>(mine.nb.slot[j]));
            }
        }
    });
}

MovesSince::MovesSince(const ParticleSet& reference)
    : x_(reference.x.begin(), reference.x.end()), y_(reference.y.begin(), reference.y.end()),
      z_(reference.z.begin(), reference.z.end()), dimension_(reference.dimension)
{
    if (reference.box) edges_ = reference.box->edges, inverse_ = reference.box->edges.inverse();
}

Eigen::Vector3d MovesSince::of(const ParticleSet& set, std::size_t i) const
{
    const Eigen::Vector3d d(set.x[i] - x_[i], set.y[i] - y_[i], set.z[i] - z_[i]);
    if (!edges_) return d;
    Eigen::Vector3d f = *inverse_ * d;
    bool wrapped = false;
    for (int a = 0; a < dimension_; ++a) {
        const double turns = std::round(f[a]);
        f[a] -= turns, wrapped = wrapped || turns != 0;
    }
    // A particle that has not crossed a side keeps its plain difference, to the bit.
    return wrapped ? Eigen::Vector3d(*edges_ * f) : d;
}

double MovesSince::farthest(const ParticleSet& set, int threads) const
{
    if (set.size() != size()) return INFINITY;
    const double farthest2 = parallel_reduce(
        set.size(), threads, 0.0, [&](std::size_t i, double& m) { m = std::max(m, of(set, i).squaredNorm()); },
        [](double& total, double block) { total = std::max(total, block); });
    return std::sqrt(farthest2);
}

bool PairList::follow(const ParticleSet& set)
{
    const int threads = grid_->threads();
    if (!(since_build_->farthest(set, threads) <= skin_ / 2)) return false;
    ParallelFor pass;
    pass.run_blocks(grid_->points(), particle_block_size, threads,
                    [&](std::size_t, std::size_t begin, std::size_t end) {
                        for (std::size_t p = begin; p < end; ++p) {
                            const Eigen::Vector3d d = since_build_->of(set, grid_->source(p));
                            x_[p] = grid_->x()[p] + d.x(), y_[p] = grid_->y()[p] + d.y(), z_[p] = grid_->z()[p] + d.z();
                        }
                    });
    return true;
}

bool PairList::gather_listed_cluster(const TileList& list, std::size_t c, const double* a, ClusterCandidates& out) const
{
    const Range r = cluster_candidates_[c];
    out.count = r.end - r.begin, out.with_a = a != nullptr, out.with_b = false, out.with_key = true;
    if (out.count == 0) return false;
    out.reserve(out.count + neighbour_lanes);
    const std::uint32_t* points = list.candidates.data() + r.begin;
    for (std::size_t k = 0; k < out.count; ++k) {
        const std::uint32_t p = points[k];
        out.x[k] = x_[p], out.y[k] = y_[p], out.z[k] = z_[p], out.key[k] = order_->keys[p];
        if (a) out.a[k] = a[p];
    }
    return true;
}

namespace {

// The listed candidates of a particle, one after another: positions, a (where the cluster has
// it) and, as b, each one's place among the cluster's candidates; and room for the
// compress's reads past the last.
void read_listed(const std::uint32_t* __restrict listed, std::size_t n, const ClusterCandidates& cluster,
                 ClusterCandidates& out)
{
    out.reserve(n + neighbour_lanes);
    const double* __restrict cx = cluster.x.data(), * __restrict cy = cluster.y.data(), * __restrict cz = cluster.z.data();
    double* __restrict x = out.x.data(), * __restrict y = out.y.data(), * __restrict z = out.z.data();
    double* __restrict b = out.b.data();
    for (std::size_t j = 0; j < n; ++j) {
        const std::uint32_t k = listed[j];
        x[j] = cx[k], y[j] = cy[k], z[j] = cz[k], b[j] = k;
    }
    if (cluster.with_a) {
        const double* __restrict ca = cluster.a.data();
        double* __restrict a = out.a.data();
        for (std::size_t j = 0; j < n; ++j) a[j] = ca[listed[j]];
    }
    for (std::size_t j = n; j < n + neighbour_lanes; ++j) x[j] = y[j] = z[j] = b[j] = out.a[j] = 0;
    out.count = n;
}

} // namespace

void PairList::gather_listed(const TileList& list, std::size_t c, std::size_t p, ListScratch& mine) const
{
    const ClusterCandidates& cluster = mine.cluster;
    const Range r = point_neighbours_[p];
    const double reach2 = search_reach(support_) * search_reach(support_);
    ClusterCandidates& listed = mine.listed;
    Neighbours& nb = mine.nb;
    read_listed(list.neighbours.data() + r.begin, r.end - r.begin, cluster, listed);
    const double at[3] = {x_[p], y_[p], z_[p]}, *xyz[3] = {listed.x.data(), listed.y.data(), listed.z.data()};
    std::size_t zeros = 0;
    const std::size_t m = compress_run(xyz, cluster.with_a ? listed.a.data() : nullptr, listed.b.data(), listed.count,
                                       at, reach2, nb, zeros);
    for (std::size_t j = 0; zeros > 0 && j < listed.count; ++j) {
        const double d[3] = {listed.x[j] - at[0], listed.y[j] - at[1], listed.z[j] - at[2]};
        const auto k = static_cast<std::size_t>(listed.b[j]);
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] == 0)
            fail_coincident(set_name_, grid_->id(p), grid_->id(list.candidates[cluster_candidates_[c].begin + k]), at,
                            d);
    }
    std::copy(nb.b.begin(), nb.b.begin() + static_cast<std::ptrdiff_t>(m), nb.slot.begin());
    for (std::size_t j = m; j < m + neighbour_lanes; ++j)
        nb.dx[j] = nb.dy[j] = nb.dz[j] = nb.a[j] = nb.b[j] = 0, nb.r2[j] = reach2,
        nb.slot[j] = static_cast<double>(cluster.count);
    nb.count = m;
}

std::size_t PairList::listed_pairs() const
{
    std::size_t pairs = 0;
    for (const TileList& list : tile_lists_) pairs += list.neighbours.size();
    return pairs;
}

} // namespace sphkern
