// A code's parameter swept on a particle set (`sphkern assess KERNEL FILE --code swift
// --eta-range A,B`): the verdict of assess_particles at each value, and the setting the set
// needs, the smallest value at which condition (22) holds on its interior.
#pragma once

#include "requests/assess_particles.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdio>
#include <optional>
#include <vector>

namespace sphkern {

struct SweepPoint {
    double value = 0; // the code's parameter
    double mean_neighbours = 0;
    ParticleRegion interior;
    double margin = 0; // epsilon less the interior's worst
    bool holds = false;
};

struct CodeSweepResult {
    std::string code, parameter;
    double epsilon = 0.01;
    std::vector<SweepPoint> points;
    std::optional<double> needed; // the smallest value that holds
};

// `steps` + 1 values from `from` to `to` (checked: 0 < from < to, 1 to 100 steps, named by
// `range` and `steps_source`). Error(usage) naming the range where no value holds, with the best.
CodeSweepResult sweep_code_setting(const Kernel& kernel, const ParticleSet& set, ParticleArguments given,
                                   const ParticleSources& sources, double epsilon, double from, double to, int steps,
                                   const ValueSource& range, const ValueSource& steps_source);
nlohmann::json code_sweep_json(const CodeSweepResult& result);
void print_code_sweep(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const CodeSweepResult& result);

} // namespace sphkern
