// The particle engine's pass that takes each pair once, for sums whose pair terms both
// particles share (one h): a particle is given only its neighbours whose key is above its own
// (PairOrder), and the visitor adds each pair's term to both: half the kernel calls of
// pair_pass, and a third less of each particle's search (BENCHMARKS.md).
//
// A pair's second particle lies in the first's row of bins (along x), the next row along y,
// or one of the three beside it in the next layer along z. The grid is cut into tiles, each a
// block of rows of one layer (a block a fixed share of the layer, at least two rows), and the
// tiles coloured by the parity of their layer and of their block, so that no two tiles of one
// colour write to one particle; in a set one layer thick, the blocks alone. The colours run one
// after another, each tile on one thread in the grid's sweep order (its candidates stay in
// cache, as in pair_pass). Every particle receives its terms in one order whatever the thread
// count: the sums are the same bits on any number of threads (not the gather's bits: the
// order of the terms differs).
#pragma once

#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/progress.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

struct SymmetricPassInputs {
    double reach = 0;          // every particle's search reach (one h): at most the grid's
    const double* a = nullptr; // gathered per neighbour into nb.a, unless null (grid's point order)
    const double* b = nullptr; // likewise into nb.b
    bool with_r2 = true;       // nb.r2 written (else the visitor takes distances from dx, dy, dz)
    std::string progress;      // the progress line's label; empty: none
    bool count_pairs = false;  // the pass returns the pairs (else 0)
    // The grid's pair order, from a caller that runs several passes on one grid; null: made here.
    const PairOrder* order = nullptr;
};

// A tile: the clusters [begin, end) of a block of rows of one layer; `index` counts the tiles
// colour after colour.
struct PairTile {
    std::size_t begin, end, index;
};
// The tiles of each colour, in sweep order. They depend on the grid alone.
std::vector<std::vector<PairTile>> tiles_by_colour(const NeighbourGrid& grid);

// Adds terms[q][j] to cluster_sums[Q nb.slot[j] + q] for each of nb's neighbours: the pair's
// other terms, to the neighbour's place among its cluster's candidates (in L1; symmetric_pair_pass
// adds them to the particles' sums once the cluster is done).
template <std::size_t Q>
inline void add_to_pairs(const Neighbours& nb, const std::array<const double*, Q>& terms,
                         double* __restrict cluster_sums)
{
    const double* __restrict slot = nb.slot.data();
    for (std::size_t j = 0; j < nb.count; ++j) {
        double* to = cluster_sums + Q * static_cast<std::int64_t>(slot[j]);
        for (std::size_t q = 0; q < Q; ++q) to[q] += terms[q][j];
    }
}

// The pairs of p's neighbours nb as a gather counts them: each paired neighbour twice, an
// unpaired one once.
inline std::size_t gathered_pairs(const Neighbours& nb, const ClusterCandidates& cluster, double unpaired)
{
    if (!cluster.any_unpaired) return 2 * nb.count;
    std::size_t paired = 0;
    for (std::size_t j = 0; j < nb.count; ++j) paired += cluster.key[static_cast<std::size_t>(nb.slot[j])] != unpaired;
    return nb.count + paired;
}

// f(p, i) for every visited point p of the grid and its particle i, on `threads` threads:
// where a pass's sums by point become each particle's result.
template <class F>
void for_each_visited(const NeighbourGrid& grid, int threads, const F& f)
{
    ParallelFor pass;
    pass.run(grid.points(), threads, [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p)
            if (grid.visited(p)) f(p, grid.source(p));
    });
}

// work(thread, tile) for every tile of `colours`, the colours one after another, each tile on
// one thread (tiles of one colour never write to one particle); a progress line by tile where
// `label` is not empty.
template <class Work>
void for_each_tile_by_colour(const std::vector<std::vector<PairTile>>& colours, int threads, const std::string& label,
                             const Work& work)
{
    std::size_t tiles = 0, finished = 0;
    for (const auto& tiles_of_colour : colours) tiles += tiles_of_colour.size();
    std::optional<Progress> progress;
    if (!label.empty()) progress.emplace(label, tiles);
    for (const auto& tiles_of_colour : colours) {
        std::atomic<std::size_t> next{0};
        ParallelFor pass;
        pass.run(static_cast<std::size_t>(std::max(1, threads)), threads, [&](int thread, std::size_t, std::size_t) {
            for (std::size_t t; pass.keep_going() && (t = next.fetch_add(1)) < tiles_of_colour.size();) {
                if (progress && thread == 0) progress->reach(finished + t, "tile " + std::to_string(finished + t));
                work(thread, tiles_of_colour[t]);
            }
        });
        finished += tiles_of_colour.size();
    }
}

// Adds each candidate's cluster sums (Q a candidate) to its particle's (an unpaired one's to
// the slot not read): where a cluster's pairs' other terms reach the particles.
template <std::size_t Q>
void add_cluster_sums(const ClusterCandidates& cluster, const double* cluster_sums, double* sums)
{
    for (std::size_t k = 0; k < cluster.count; ++k) {
        double* to = sums + Q * static_cast<std::int64_t>(cluster.key[k]);
        const double* from = cluster_sums + Q * k;
        for (std::size_t q = 0; q < Q; ++q) to[q] += from[q];
    }
}

// A thread's room for one cluster at a time.
struct ClusterScratch {
    ClusterCandidates cluster;
    Neighbours nb;
    std::vector<double> cluster_sums;
    std::size_t pairs = 0;
};

// Each pair once, on sums of Q quantities for each point of the grid (`sums`, Q to a point,
// and Q more for the unpaired key, which are not read): visit(p, nb, cluster_sums) for every
// particle point p, with nb holding its neighbours whose key is above p's (dx, dy, dz, r2
// unless !with_r2, a, b and slot, padded to neighbour_lanes). The visitor adds p's own terms
// to sums[Q p + q] and each pair's other terms by add_to_pairs to cluster_sums, which the pass
// then adds to the neighbours' sums. Returns the pairs as a gather counts them: each paired
// neighbour twice, an unpaired one (a ghost) once; with count_pairs.
template <std::size_t Q, class Visit>
std::size_t symmetric_pair_pass(const NeighbourGrid& grid, const std::string& set_name, const SymmetricPassInputs& in,
                                int threads, double* sums, const Visit& visit)
{
    const std::optional<PairOrder> own_order = in.order ? std::nullopt : std::optional<PairOrder>(grid);
    const PairOrder& order = in.order ? *in.order : *own_order;
    std::vector<ClusterScratch> scratch(static_cast<std::size_t>(std::max(1, threads)));
    const double unpaired = unpaired_key(grid);
    for_each_tile_by_colour(tiles_by_colour(grid), threads, in.progress, [&](int thread, const PairTile& tile) {
        ClusterScratch& mine = scratch[static_cast<std::size_t>(thread)];
        ClusterCandidates& cluster = mine.cluster;
        for (std::size_t c = tile.begin; c < tile.end; ++c) {
            gather_cluster(grid, c, {nullptr, in.reach}, in.a, in.b, cluster, &order);
            if (cluster.count == 0) continue;
            mine.cluster_sums.assign(Q * (cluster.count + 1), 0.0);
            for (std::size_t p = grid.cluster_begin(c); p < grid.cluster_end(c); ++p) {
                if (!grid.visited(p)) continue;
                gather_from_cluster(grid, cluster, p, in.reach * in.reach, set_name, mine.nb, in.with_r2);
                visit(p, mine.nb, mine.cluster_sums.data());
                if (in.count_pairs) mine.pairs += gathered_pairs(mine.nb, cluster, unpaired);
            }
            add_cluster_sums<Q>(cluster, mine.cluster_sums.data(), sums);
        }
    });
    std::size_t pairs = 0;
    for (const ClusterScratch& mine : scratch) pairs += mine.pairs;
    return pairs;
}

} // namespace sphkern
