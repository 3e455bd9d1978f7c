// The particle engine's one pass over every particle and its neighbours, which the measures,
// the block's sums, relax's densities and forces and g(r) all run: on `threads` threads, the
// clusters of the grid in cell order, each cluster's candidates gathered once, then each of
// its particles (ghosts and neighbours-only particles skipped) given its neighbours within its
// own reach. A visitor writes per particle or adds integers per thread, so which thread takes
// which cluster changes no result. Progress is shown by the first thread, in the runs of clusters taken by all.
#pragma once

#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/progress.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

namespace sphkern {

struct PairPassInputs {
    PointValues reach;                  // each particle's search reach (search_reach of its support radius)
    const double* a = nullptr;          // gathered per neighbour into nb.a, unless null (grid's point order)
    const double* b = nullptr;          // likewise into nb.b
    bool with_r2 = true;                // nb.r2 written (else the visitor takes distances from dx, dy, dz)
    std::string progress;               // the progress line's label; empty: none
    const std::uint8_t* only = nullptr; // per point: visit where nonzero (null: every particle)
};

// visit(thread, p, nb) for every particle point p of the grid, with nb holding its neighbours
// (dx, dy, dz, r2 unless !with_r2, a and b, padded to neighbour_lanes); then done(thread) once
// per thread, after its last particle. `set_name` names the set in an error.
template <class Visit, class Done>
void pair_pass(const NeighbourGrid& grid, const std::string& set_name, const PairPassInputs& in, int threads,
               const Visit& visit, const Done& done)
{
    // Runs of clusters are taken as threads become free: a run's clusters are neighbours and
    // share their candidates in cache, and no thread waits on another whose share held more
    // particles (the clusters of ghosts at a periodic box's faces hold none to visit).
    const std::size_t clusters = grid.clusters(), workers = static_cast<std::size_t>(std::max(1, threads));
    const std::size_t run = std::max<std::size_t>(1, clusters / (16 * workers));
    std::atomic<std::size_t> next{0};
    ParallelFor pass;
    pass.run(workers, threads, [&](int thread, std::size_t, std::size_t) {
        ClusterCandidates cluster;
        Neighbours nb;
        std::optional<Progress> progress;
        if (thread == 0 && !in.progress.empty()) progress.emplace(in.progress, (clusters + run - 1) / run);
        for (std::size_t begin; pass.keep_going() && (begin = next.fetch_add(run)) < clusters;) {
            if (progress) progress->reach(begin / run, "cluster " + std::to_string(begin));
            for (std::size_t c = begin; c < std::min(clusters, begin + run); ++c) {
                if (in.only && std::none_of(in.only + grid.cluster_begin(c), in.only + grid.cluster_end(c),
                                            [](std::uint8_t v) { return v != 0; }))
                    continue;
                gather_cluster(grid, c, in.reach, in.a, in.b, cluster);
                for (std::size_t p = grid.cluster_begin(c); p < grid.cluster_end(c); ++p) {
                    if (!grid.visited(p) || (in.only && !in.only[p])) continue;
                    const double reach = in.reach[p];
                    gather_from_cluster(grid, cluster, p, reach * reach, set_name, nb, in.with_r2);
                    visit(thread, p, nb);
                }
            }
        }
        done(thread);
    });
}

} // namespace sphkern
