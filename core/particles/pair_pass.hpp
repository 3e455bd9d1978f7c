// The particle engine's one pass over every particle and its neighbours, which the measures,
// the block's sums, relax's densities and forces and g(r) all run: on `threads` threads, the
// clusters of the grid in cell order (a thread's clusters contiguous, so that neighbouring
// clusters share their candidates in cache), each cluster's candidates gathered once, then
// each of its particles (ghosts skipped) given its neighbours within its own reach. Progress
// is shown from the first thread's share (every thread has as many clusters).
#pragma once

#include "particles/neighbour_gather.hpp"
#include "particles/neighbour_grid.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/progress.hpp"

#include <optional>
#include <string>

namespace sphkern {

struct PairPassInputs {
    PointValues reach;         // each particle's search reach (search_reach of its support radius)
    const double* a = nullptr; // gathered per neighbour into nb.a, unless null (grid's point order)
    const double* b = nullptr; // likewise into nb.b
    bool with_r2 = true;       // nb.r2 written (else the visitor takes distances from dx, dy, dz)
    std::string progress;      // the progress line's label; empty: none
};

// visit(thread, p, nb) for every particle point p of the grid, with nb holding its neighbours
// (dx, dy, dz, r2 unless !with_r2, a and b, padded to neighbour_lanes); then done(thread) once
// per thread, after its last particle. `set_name` names the set in an error.
template <class Visit, class Done>
void pair_pass(const NeighbourGrid& grid, const std::string& set_name, const PairPassInputs& in, int threads,
               const Visit& visit, const Done& done)
{
    ParallelFor pass;
    pass.run(grid.clusters(), threads, [&](int thread, std::size_t begin, std::size_t end) {
        ClusterCandidates cluster;
        Neighbours nb;
        std::optional<Progress> progress;
        if (thread == 0 && !in.progress.empty()) progress.emplace(in.progress, (end - begin + 255) / 256);
        for (std::size_t c = begin; c < end && pass.keep_going(); ++c) {
            if (progress && ((c - begin) & 255) == 255) progress->step(std::to_string(c - begin + 1) + " clusters");
            gather_cluster(grid, c, in.reach, in.a, in.b, cluster);
            for (std::size_t p = grid.cluster_begin(c); p < grid.cluster_end(c); ++p) {
                if (grid.is_ghost(p)) continue;
                const double reach = in.reach[p];
                gather_from_cluster(grid, cluster, p, reach * reach, set_name, nb, in.with_r2);
                visit(thread, p, nb);
            }
        }
        done(thread);
    });
}

} // namespace sphkern
