// One verdict on a code's setting on a particle set (`sphkern assess KERNEL FILE --code ...`):
// h as `particles --code` sets it, the particle statistics, and condition (22) judged on the
// interior particles (the smallest eigenvalue of the first-order correction matrix I + E above
// 0.75, Marrone et al. 2010; the others are at or near a free surface and reported beside): the
// middle 98% (p1 to p99) of e0, each particle's density error against its own volume, and of
// eps_gradp within epsilon, with its margin. The linear stability and a recommended setting
// need a lattice: the verdict names the lattices to assess instead.
#pragma once

#include "requests/particles_request.hpp"

#include <nlohmann/json_fwd.hpp>

#include "particles/particle_statistics.hpp"

#include <cstdio>
#include <string>

namespace sphkern {

// Particles of one kind (interior, or at or near a free surface) and their errors.
struct ParticleRegion {
    std::size_t particles = 0;
    Summary e0, eps_gradp, lambda_min;
};

// Interior: lambda_min(I + E) above this (Marrone et al. 2010's bound of a free surface's neighbourhood).
inline constexpr double interior_lambda = 0.75;

struct ParticleAssessResult {
    ParticleAnswer answer;
    ParticleRegion interior, surface;
    double worst = 0;        // the larger of max(|p1|, |p99|) of eps_rho and of eps_gradp
    std::string worst_name;  // "e0" or "eps_gradp", of the interior
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
