// One verdict on a code's setting on a particle set (`sphkern assess KERNEL FILE --code ...`):
// h as `particles --code` sets it, the particle statistics, and condition (22) judged on the
// interior particles (the smallest eigenvalue of the first-order correction matrix I + E above
// 0.75, Marrone et al. 2010; the others are at or near a free surface and reported beside): the
// middle 98% (p1 to p99) of e0, each particle's density error against its own volume, and of
// eps_gradp within epsilon, with its margin; and the linear stability of the same setting on
// every shipped lattice of the set's dimension (the code's parameter, or the set's mean h over
// the mean spacing, on each), under the code's pressure at rest and h model. A recommended
// setting needs a lattice: the verdict names the stable ones to assess.
#pragma once

#include "requests/assess_request.hpp"
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

// The same setting on one lattice: its k and the linear verdict, or why it has none there.
struct LatticeStability {
    std::string lattice;
    double k = 0;
    AssessStability stability;
    std::string refused; // a setting the lattice cannot take (past its sums' reach, no neighbour)
};

struct ParticleAssessResult {
    ParticleAnswer answer;
    ParticleRegion interior, surface;
    double worst = 0;       // the larger of max(|p1|, |p99|) of eps_rho and of eps_gradp
    std::string worst_name; // "e0" or "eps_gradp", of the interior
    double epsilon = 0.01;
    std::vector<LatticeStability> lattices; // every shipped lattice of the set's dimension
    std::string pressure;                   // the pressure at rest the verdicts assume, in words
    std::string verdict;                    // the one line
    bool accurate() const { return worst <= epsilon; }
};

// `given` holds the code (with its parameter, or alone for a stored h); Error naming the source
// otherwise. Without `lattice_stability` (a sweep's values) no lattice is judged.
ParticleAssessResult assess_particles(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                      const ParticleSources& sources, double epsilon, bool lattice_stability = true);
nlohmann::json particle_assess_document(const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                                        const ParticleAssessResult& result);
void print_particle_assess(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const ParticleArguments& given,
                           const ParticleAssessResult& result);

} // namespace sphkern
