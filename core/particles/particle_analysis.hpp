// One request on a particle set, from any front end: how to give h and volumes, where
// gravity points, and one h or a sweep over eta or N_H; and what it answers: the statistics
// of every measure (and the per-particle values of a single h).
#pragma once

#include "kernels/kernel.hpp"
#include "particles/particle_measures.hpp"
#include "particles/particle_statistics.hpp"
#include "particles/particle_volumes.hpp"
#include "particles/smoothing_lengths.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sphkern {

struct SmoothingSweep {
    SmoothingRule rule = SmoothingRule::eta; // eta or nh
    double from = 0, to = 0;
    int steps = 10; // steps + 1 values, evenly spaced
};

struct ParticleRequest {
    SmoothingSpec smoothing;
    std::optional<SmoothingSweep> sweep;
    std::optional<VolumeModel> volume;      // default: default_volume_model
    std::vector<double> given_volumes;      // non-empty: these volumes, whatever `volume` says
    std::optional<Eigen::Vector3d> gravity; // default: the set's
    double depth = 1;                       // of eps_gradp_sum, in units of h
    std::optional<double> rho0;             // of eps_rho where the set has masses
    int threads = 0;
    std::size_t histogram_bins = 0;
    bool vectors = true; // keep e1, m1 and E per particle (per-particle outputs); else their magnitudes only
};

// The statistics of one h (one value of a sweep).
struct ParticlePoint {
    double eta = 0, nh = 0; // h = eta V̄^(1/D) and N_H = c_D (R eta)^D for the mean h
    double h_min = 0, h_max = 0;
    double mean_neighbours = 0;
    std::vector<std::pair<std::string, Summary>> statistics; // e0, eps_rho, eps_gradp, ... in a fixed order
    std::vector<std::pair<std::string, Histogram>> histograms;
    double seconds = 0, cpu_seconds = 0; // of the sums: wall time, and CPU time of all threads
    std::size_t pairs = 0;
    const Summary& statistic(const std::string& name) const; // std::logic_error for a name not computed
};

struct ParticleAnswer {
    std::size_t particles = 0; // measured (a PySPH file's first array)
    VolumeModel volume = VolumeModel::uniform;
    double mean_volume = 0, rho0 = 1, spacing = 1;
    Eigen::Vector3d gravity;
    PerParticle h, volumes;                   // of the single h (h not kept for sweeps)
    std::optional<ParticleMeasures> measures; // of the single h
    std::vector<ParticlePoint> points;        // one, or one per sweep value
    int threads = 1;
    PhaseTimes phases; // volumes, h, grid, sums, statistics (a front end adds read and write)
};

// Checks the request against the set (one line per problem), then measures.
ParticleAnswer analyse_particles(const Kernel& kernel, const ParticleSet& set, const ParticleRequest& request);

// The statistics of a point, in this order; the first four have histograms.
inline constexpr const char* measure_names[] = {"e0",   "eps_rho", "eps_gradp", "eps_gradp_sum",
                                                "|e1|", "|m1|",    "||E||_F",   "neighbours"};
inline constexpr std::size_t measures_with_histograms = 4;

// A point's h over the mean spacing, N_H and h range from the statistics of h (`unit` the
// mean spacing V̄^(1/D)); and one line for statistics that overflow a double (Error(input)),
// so that no non-finite number is printed.
void finish_point(ParticlePoint& point, const Summary& h, double unit, double support, const ParticleSet& set,
                  double rho0);

} // namespace sphkern
