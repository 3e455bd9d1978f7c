// Each pair once, kept while the particles move (a Verlet list with a buffer, as molecular
// dynamics codes keep their cluster pairs): the symmetric pass's search, run once with the
// support radius and a skin, lists every cluster's candidates and every particle's neighbours
// among them; a pass over the list reads each particle's listed neighbours at their present
// positions and keeps those within the support, without the grid's runs. The list holds while
// no particle has moved more than half the skin since it was built: two particles that close
// in by at most the skin were within the support and the skin, so listed.
//
// Its passes visit the tiles, clusters and particles of the grid it was built on, in the same
// order as symmetric_pair_pass: built with no skin and read where it was built, the same bits;
// after moves, the pairs a fresh search finds (the same ones) in the old grid's order, which is
// not the new grid's: agreement to rounding (1e-13), and the same bits on any thread count.
#pragma once

#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "particles/engine/symmetric_pair_pass.hpp"
#include "particles/particle_set.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// Each particle's displacement since a reference: its present position less the one kept, the
// nearest image of it in a periodic box (a particle wrapped across a side has moved a little).
class MovesSince {
public:
    explicit MovesSince(const ParticleSet& reference);
    std::size_t size() const { return x_.size(); }
    Eigen::Vector3d of(const ParticleSet& set, std::size_t i) const;
    // The longest displacement of any particle (infinite for a set of another size).
    double farthest(const ParticleSet& set, int threads) const;

private:
    std::vector<double> x_, y_, z_;
    int dimension_ = 3;
    std::optional<Eigen::Matrix3d> edges_, inverse_; // the periodic box's
};

class PairList {
public:
    // Pairs within `support` (one support radius R h for every particle) and `skin` (0 or
    // more; shortened where the periodic box is narrower than twice their sum). Throws what
    // NeighbourGrid and the search throw (a box too narrow for the support, coincident particles).
    PairList(const ParticleSet& set, double support, double skin, int threads);

    double support() const { return support_; }
    double skin() const { return skin_; }
    const NeighbourGrid& grid() const { return *grid_; }

    // Moves the list's points with the particles of `set` (the set it was built on, moved):
    // each by its particle's displacement since the build, the nearest image of it in a
    // periodic box. False, with nothing moved, where a particle has moved more than half the
    // skin (or the set has another size): the list no longer holds; rebuild it.
    bool follow(const ParticleSet& set);
    // The list of `set` as it is now (the memory of the last kept for the next).
    void rebuild(const ParticleSet& set);

    // As symmetric_pair_pass (its visitor and sums, with dx, dy, dz, r2, slot and a unless null
    // per neighbour, a in the grid's point order) over the listed pairs within the support.
    template <std::size_t Q, class Visit>
    void pass(const double* a, int threads, double* sums, const Visit& visit) const
    {
        std::vector<ListScratch> scratch(static_cast<std::size_t>(std::max(1, threads)));
        for_each_tile_by_colour(colours_, threads, "", [&](int thread, const PairTile& tile) {
            ListScratch& mine = scratch[static_cast<std::size_t>(thread)];
            const TileList& list = tile_lists_[tile.index];
            for (std::size_t c = tile.begin; c < tile.end; ++c) {
                if (!gather_listed_cluster(list, c, a, mine.cluster)) continue;
                mine.cluster_sums.assign(Q * (mine.cluster.count + 1), 0.0);
                for (std::size_t p = grid_->cluster_begin(c); p < grid_->cluster_end(c); ++p) {
                    if (!grid_->visited(p)) continue;
                    gather_listed(list, c, p, mine);
                    visit(p, mine.nb, mine.cluster_sums.data());
                }
                add_cluster_sums<Q>(mine.cluster, mine.cluster_sums.data(), sums);
            }
        });
    }

    // The listed pairs, each pair once (within the support and the skin).
    std::size_t listed_pairs() const;

private:
    struct ListScratch : ClusterScratch {
        ClusterCandidates listed; // a particle's listed candidates, one after another
    };
    // A tile's clusters' candidates (points) and its particles' neighbours (places among their
    // cluster's candidates), one after another.
    struct TileList {
        std::vector<std::uint32_t> candidates, neighbours;
    };
    struct Range {
        std::size_t begin = 0, end = 0;
    };
    void build();
    // Cluster c's candidates at their present positions, with a and keys; false for none.
    bool gather_listed_cluster(const TileList& list, std::size_t c, const double* a, ClusterCandidates& out) const;
    // Point p's (of cluster c) listed neighbours within the support, as gather_from_cluster leaves them.
    void gather_listed(const TileList& list, std::size_t c, std::size_t p, ListScratch& mine) const;

    double support_, skin_;
    int threads_;
    std::optional<NeighbourGrid> grid_;
    std::optional<PairOrder> order_;
    std::vector<std::vector<PairTile>> colours_;
    std::vector<TileList> tile_lists_;
    std::vector<Range> cluster_candidates_; // per cluster: its candidates in its tile's list
    std::vector<Range> point_neighbours_;   // per point: its neighbours in its tile's list
    std::vector<double> x_, y_, z_;         // the points' present positions
    std::optional<MovesSince> since_build_;
    std::string set_name_;
};

} // namespace sphkern
