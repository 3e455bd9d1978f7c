// The neighbours of one point of a NeighbourGrid inside a radius: their displacements,
// distances and two per-point values gathered alongside (a volume and a mass, or what a
// caller needs), in the grid's fixed order. The loops are written so that they vectorise.
#pragma once

#include "support/error.hpp"

#include "particles/engine/neighbour_grid.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sphkern {

// Two particles at one position (or too close for their squared distance to be a number): no
// sum over them is defined. Its ids let a caller that moved the particles say how they got there.
class CoincidentParticles : public Error {
public:
    CoincidentParticles(const std::string& message, std::uint64_t a, std::uint64_t b)
        : Error(ExitCode::input, message), first(a), second(b)
    {}
    std::uint64_t first, second;
};

// Two particles (ids i and k) at a squared distance of 0: one at `at`, the other d from it.
[[noreturn]] void fail_coincident(const std::string& set_name, std::uint64_t i, std::uint64_t k, const double* at,
                                  const double* d);

// One point's neighbours (x_j - x_i, r2, r on request, the gathered values a_j and b_j, each
// pair once their places among the cluster's candidates) and room for q, W, W' and 1 / r of a caller.
struct Neighbours {
    std::vector<double> r2, dx, dy, dz, r, q, a, b, w, dw, inv_r, slot;
    std::vector<std::uint32_t> index; // scratch of the candidate pass
    std::size_t count = 0;
    void reserve(std::size_t n);
};

// The fused pair loops take neighbours in groups of this many; gather_from_cluster pads to it.
inline constexpr std::size_t neighbour_lanes = 8;
// n neighbours and their padding: n rounded up to a multiple of neighbour_lanes.
inline constexpr std::size_t padded_count(std::size_t n)
{
    return (n + neighbour_lanes - 1) / neighbour_lanes * neighbour_lanes;
}

// How the candidate passes keep the points inside: one at a time (branch-free), with AVX2
// (a permutation per mask: of four points near a box, of eight indices of a particle's
// neighbours, whose points are then gathered) or eight at a time (AVX-512 compress). Each keeps the same points
// in the same order; the widest the processor has is used unless a test chooses another.
enum class CompressPath { scalar, avx2, avx512 };
CompressPath widest_compress_path();
void use_compress_path(CompressPath path); // not thread-safe: for tests, before any pass

// The candidates shared by the particles of one cluster of the grid (as in GROMACS's cluster
// pairs): every point within the cluster's reach (the largest support radius of its
// particles) of the box around them, in the grid's fixed order, contiguous, so that each
// particle's pass over them stays in L1 and the rows are cut once per cluster, not per particle.
struct ClusterCandidates {
    std::vector<double> x, y, z, a, b, key; // a, b and key only when gathered with them
    std::size_t count = 0;
    double reach = 0;
    bool with_a = true, with_b = false, with_key = false;
    bool any_unpaired = false; // each pair once: a candidate may have the unpaired key (a ghost near)
    void reserve(std::size_t n);
};

// Each pair once (symmetric_pair_pass): the key of a point orders the pairs. A visited
// particle's key is its point, and a particle takes only the neighbours whose key is above its
// own, so a pair of particles is taken by the first of them; a ghost or a neighbours-only
// point has the unpaired key, the grid's point count, above every particle's: its pair is
// taken from the particle's side only, and from the other particle's side through that one's
// own ghost (a pair across a periodic side is evaluated twice, once for each particle, as the
// gather does). Sums by point have one slot more, at the unpaired key, that takes the terms
// of the unpaired and is not read: the scatter needs no branch.
inline double unpaired_key(const NeighbourGrid& grid) { return static_cast<double>(grid.points()); }
struct PairOrder {
    std::vector<double> keys;                   // per point
    std::vector<std::uint32_t> unpaired_before; // per point and one past the last: unpaired points before it
    explicit PairOrder(const NeighbourGrid& grid);
};

// A value per point of the grid (in its point order), or one for every point (per_point null:
// nothing to gather or read when every particle has the same).
struct PointValues {
    const double* per_point = nullptr;
    double all = 0;
    double operator[](std::size_t p) const { return per_point ? per_point[p] : all; }
};

// The candidates of cluster c for particles whose support radius is reach[point], with a[j]
// unless a is null and b[j] unless b is null per point (grid's point order). count = 0 for a
// cluster with no visited point (ghosts and neighbours-only particles). With a pair order,
// each pair once: only the candidates whose key is above the cluster's first particle's (the
// runs of points before it that hold no unpaired point are not read).
void gather_cluster(const NeighbourGrid& grid, std::size_t c, PointValues reach, const double* a, const double* b,
                    ClusterCandidates& out, const PairOrder* order = nullptr);

// The neighbours of point p of the cluster within sqrt(reach2), p itself left out, from
// the cluster's candidates in one pass that keeps the points inside (by the widest
// CompressPath), with r2, dx, dy, dz, a and b (a or b not written if the cluster has none;
// r only by fill_distances). After the `count` neighbours, up to the next multiple of neighbour_lanes,
// entries with a = b = dx = dy = dz = 0 and r2 = reach2. Without r2 (with_r2 false) the
// neighbours' r2 is not written (one compress fewer per eight candidates, for a caller that
// computes it again from dx, dy, dz). With the cluster's keys, each pair once: only the
// neighbours whose key is above p's, their places among the cluster's candidates in nb.slot
// (the place past the last in the padding).
// Throws Error(input) naming both ids for another particle at p's position.
void gather_from_cluster(const NeighbourGrid& grid, const ClusterCandidates& cluster, std::size_t p, double reach2,
                         const std::string& set_name, Neighbours& nb, bool with_r2 = true);

// The points of one run (positions xyz[0..2], values a and b unless null; n of them, with
// room for neighbour_lanes more after) within sqrt(reach2) of `at` with r2 > 0, written to nb
// from its start (dx, dy, dz, r2, a, b) by the widest CompressPath; returns how many, and
// adds the points at r2 = 0 to `zeros`.
std::size_t compress_run(const double* const* xyz, const double* a, const double* b, std::size_t n, const double* at,
                         double reach2, Neighbours& nb, std::size_t& zeros);

// `zeros` candidates of point p at r = 0: one (p itself) is right; throws Error(input) naming
// both ids for two, std::logic_error for none.
void require_alone(const NeighbourGrid& grid, std::size_t p, std::size_t zeros, const std::string& set_name);

// The radius the engine searches for a support radius R h: a hair beyond it, as the lattice
// sums count a neighbour at the support's edge (support_edge).
double search_reach(double support_radius);

// Over the first `padded` entries of nb (count neighbours, then padding): q = r / h (from
// inv_h) and 1 / r, with r = sqrt(dx^2 + dy^2 + dz^2) (r2 as the gather computes it, in the
// same order and without contraction: the same bits); past the neighbours, q = 1 / r = 0
// (W(0) and W'(0) are finite, and a term times 1 / r adds nothing).
void distances(Neighbours& nb, std::size_t padded, double inv_h);

// r = sqrt(r2) of the `count` neighbours.
void fill_distances(Neighbours& nb);

// q[j] = r[j] * factor.
void scale_distances(const double* r, std::size_t n, double factor, double* q);

} // namespace sphkern
