// The consistency errors of SPH on a particle set, per particle (share/docs/method.md
// section 11): e0 (density of a constant), eps_rho (with masses), the first moment m1, the
// gradient of a constant e1, the linear-gradient error tensor E, eps_gradp = g.E.g (the
// difference form) and the sum form's eps_gradp at a depth, and the neighbour count.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/engine/neighbour_grid.hpp"
#include "particles/particle_set.hpp"
#include "particles/per_particle.hpp"
#include "particles/smoothing_lengths.hpp"
#include "support/process/first_touch.hpp"
#include "support/process/phase_times.hpp"

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace sphkern {

// A slab of a larger set (particles/slabs): the whole set's bins and largest h, so that every
// particle of the slab's own rows sees what it sees in the whole set, in the same order. Its h
// and V are uniform only where their views say so (the whole set's), never found so in the slab.
struct MeasureSlab {
    GridWindow window;
    double h_max = 0;
};

// Views of the caller's arrays (nothing per particle is copied).
struct MeasureInputs {
    PerParticleView h;                       // sphkern's h of every particle (support R h)
    PerParticleView volume;                  // V_j
    std::span<const double> mass;            // m_j; empty: m_j = rho0 V_j, and eps_rho = e0
    double rho0 = 1;                         // the reference density of eps_rho
    double spacing = 1;                      // d of k = h / d, the argument of kernels that depend on k
    double depth = 1;                        // of the sum form, in units of h
    std::optional<Eigen::Vector3d> gravity;  // the unit g of eps_gradp; none: the set's
    int threads = 0;                         // 0: every core
    bool vectors = true;                     // keep e1, m1 and E per particle (else only their magnitudes)
    PairSmoothing pair = PairSmoothing::own; // the mean: W(r_ij, (h_i + h_j) / 2) and its gradient
    const MeasureSlab* slab = nullptr;       // a slab: only its own rows' particles measured
};

// One particle's scalar measures side by side: the sums write a particle's in one or two cache
// lines. On a disordered set a particle's place in memory is random, and an array per measure
// cost a line each, seven in all (a quarter of the sums on a Poisson set; BENCHMARKS.md).
struct MeasureRecord {
    double e0, eps_gradp, eps_gradp_sum;
    double e1_norm, m1_norm, E_norm; // |e1|, |m1| and ||E||_F
    // The smallest eigenvalue of I + E, the first-order correction matrix sum_j V_j r_ij ⊗ ∇_i W_ij:
    // 1 inside a fluid, about 0.5 on a free surface (Marrone et al. 2010 call <= 0.75 near one).
    double lambda_min;
    int neighbours; // j != i inside the support
};

// Every array is written by the threads of the sums (first touch), one value per measured
// particle (ParticleSet::measured: the neighbours-only particles have none; in a slab, only
// the particles of its own rows have theirs).
// The statistics need only the scalars (64 bytes a particle without masses); the vectors and
// the tensor (120 bytes more) are kept where a front end asks for them (MeasureInputs::vectors).
struct ParticleMeasures {
    FirstTouchVector<MeasureRecord> scalars;
    FirstTouchVector<double> eps_rho;               // empty without masses: then eps_rho = e0
    FirstTouchVector<std::array<double, 3>> e1, m1; // empty unless asked for
    FirstTouchVector<std::array<double, 6>> E;      // xx, yy, zz, xy, xz, yz; empty unless asked for
    std::size_t pairs = 0;                          // sum of the neighbour counts
    int threads = 1;
    double seconds = 0;     // the sums, without the neighbour grid
    PhaseTimes phases;      // grid and sums
    double cpu_seconds = 0; // the same, CPU time of all threads (a loaded machine's measure)
    std::size_t size() const { return scalars.size(); }
    double eps_rho_of(std::size_t i) const { return eps_rho.empty() ? scalars[i].e0 : eps_rho[i]; }
};

// Every particle's measures by direct sums over its neighbours (periodic images by the
// minimum image). With the mean pair h, j is a neighbour of i where r_ij is inside the pair's
// support R (h_i + h_j) / 2, and the sums stay in units of h_i (the results' scale). Independent of the thread count.
// Throws Error(input) for two particles at one position (naming both ids) and a non-finite kernel value (the kernel's
// fault code).
ParticleMeasures measure_particles(const Kernel& kernel, const ParticleSet& set, const MeasureInputs& inputs);

// The measures taken inside a pass that gathers each particle's neighbours for itself (the
// density solve, which measures a particle at the h it solved, from the neighbours it summed):
// the same sums as measure_particles with each particle's own h (in the order of that pass's
// list). Not for slabs or the mean pair h. One particle at a time, from any of the threads.
class MeasureCollector {
public:
    // inputs.h is not read: each particle comes with its own.
    MeasureCollector(const Kernel& kernel, const ParticleSet& set, const MeasureInputs& inputs, int threads);
    ~MeasureCollector();
    MeasureCollector(const MeasureCollector&) = delete;
    MeasureCollector& operator=(const MeasureCollector&) = delete;

    // V_j is read per neighbour (in nb.a) only where the volumes differ; m_j (in nb.b) only with masses.
    bool volumes_differ() const;
    std::span<const double> volumes() const; // every particle's V where they differ
    bool with_mass() const;
    double spacing() const; // d of the kernel's k = h / d in the measures
    // Particle i at h over the first n entries of nb: dx, dy, dz, V_j in nb.a where the volumes
    // differ, m_j in nb.b with masses; padded with zeros to padded_count(n). With
    // `kernel_values`, W and W' at h (the kernel's k from spacing()) are in nb.w and nb.dw,
    // padded with zeros too, and are not computed again.
    void measure(int thread, std::size_t i, double h, std::size_t n, Neighbours& nb, bool kernel_values = false);
    // Every particle measured once: the measures, their pairs and threads.
    ParticleMeasures finish();

private:
    struct State;
    std::unique_ptr<State> state_;
};

// ||E||_F of the stored components.
double frobenius_norm(const std::array<double, 6>& E, int dimension);

} // namespace sphkern
