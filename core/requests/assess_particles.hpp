// One verdict on a code's setting on a particle set (`sphkern assess KERNEL FILE --code ...`):
// h as `particles --code` sets it, the particle statistics, and condition (22) judged on the
// middle 98% of the particles (p1 to p99 of eps_rho and of eps_gradp within epsilon), with
// its margin. The linear stability and a recommended setting need a lattice: the verdict says
// so rather than judging them.
#pragma once

#include "requests/particles_request.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdio>
#include <string>

namespace sphkern {

struct ParticleAssessResult {
    ParticleAnswer answer;
    double worst = 0;        // the larger of max(|p1|, |p99|) of eps_rho and of eps_gradp
    std::string worst_name;  // "eps_rho" or "eps_gradp"
    double epsilon = 0.01;
    std::string verdict;     // the one line
    bool accurate() const { return worst <= epsilon; }
};

// `given` holds the code (with its parameter, or alone for a stored h); Error naming the source otherwise.
ParticleAssessResult assess_particles(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                      const ParticleSources& sources, double epsilon);
nlohmann::json particle_assess_document(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                        const ParticleAssessResult& result);
void print_particle_assess(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                           const ParticleAssessResult& result);

} // namespace sphkern
