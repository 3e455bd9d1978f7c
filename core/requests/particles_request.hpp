// One request on a particle set (`sphkern particles`, sphkern.particles, a study's particle
// section): the values as the front end gives them, built into the engine's ParticleRequest
// in one place, each value checked once and named as that front end names it.
#pragma once

#include "particles/particle_analysis.hpp"
#include "requests/code_setting.hpp"
#include "requests/smoothing_request.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// What was not given is empty.
struct ParticleArguments {
    SmoothingArguments smoothing;
    std::optional<CodeSetting> code;          // instead of eta, N_H or k: a code's own setting (one h, no sweep)
    std::optional<std::string> stored_h_code; // a code alone: the set's stored h as that code stores it
    std::optional<std::array<double, 2>> eta_range, nh_range; // a sweep over [A, B]
    int steps = 10;                                           // of a sweep
    std::optional<std::string> volume;                        // uniform, file or voronoi
    std::vector<double> volumes;                              // non-empty: one per particle (checked with the set)
    std::optional<std::vector<double>> gravity;               // as many components as the set's dimension
    double depth = 1;
    std::optional<double> rho0;
    int threads = 0;
    long long histogram = 0;
    bool per_particle_files = false; // the front end writes per-particle values (no sweep; e1, m1 and E kept)
};

// A code named with its parameter's value (`code`: h as the code sets it), or alone
// (`stored_h_code`: the set's stored h as the code stores it).
void name_code(ParticleArguments& given, const std::string& code, std::optional<double> value);

struct ParticleSources {
    SmoothingSources smoothing;
    ValueSource eta_range, nh_range, steps, volume, gravity, depth, rho0, threads, histogram, per_particle_files;
    CodeSettingSources code; // "--code" and the code's parameter ("--eta"), "code" and "value"
};
// `per_particle_files` names the outputs ("--csv and --vtk") on the command line.
ParticleSources particle_sources(FrontEnd front_end);

// The request of `kernel` on `set`, or an Error naming the first value at fault.
ParticleRequest particle_request(const ParticleArguments& given, const Kernel& kernel, const ParticleSet& set,
                                 const ParticleSources& sources);

// A sweep over eta in (0, 100] or N_H in [1, 1e5], from < to, in 1 to 1000 steps.
SmoothingSweep checked_sweep(SmoothingRule rule, double from, double to, int steps, const ValueSource& range,
                             const ValueSource& steps_source);

} // namespace sphkern
