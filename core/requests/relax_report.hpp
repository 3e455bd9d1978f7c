// What `sphkern relax` and `sphkern pairing` print and write: the run, its history and the
// quality of the set it made, as text, JSON and a history CSV.
#pragma once

#include "particles/particle_analysis.hpp"
#include "relax/glass_quality.hpp"
#include "relax/pairing_motion.hpp"
#include "relax/relaxation.hpp"
#include "requests/code_setting.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdio>
#include <ostream>
#include <vector>

namespace sphkern {

// The set a relaxation made, judged: the particle measures at the run's h, g(r), the
// nearest neighbours, and the RMS e0 of a Poisson set at the same h for reference.
struct RelaxedSet {
    ParticleAnswer measures;
    GlassQuality quality;
    double eta = 0, nh = 0; // h over the mean spacing, and D&A's neighbour number
    double poisson_rms_e0 = 0;
};

nlohmann::json relax_json(const Kernel& kernel, const RelaxSettings& settings, const RelaxResult& run,
                          const RelaxedSet& judged);
void print_relax(std::FILE* out, const Kernel& kernel, const RelaxSettings& settings, const RelaxResult& run,
                 const RelaxedSet& judged);
// step,time,rms_move,max_move,rms_e0,rms_e1,kinetic
void write_relax_history_csv(std::ostream& out, const std::vector<RelaxStep>& history);

// With the code's setting whose k the run took, if one was given ("code" in the JSON, named in the text).
nlohmann::json pairing_json(const Kernel& kernel, const Lattice& lattice, const PairingRequest& request,
                            const std::vector<PairingPoint>& points, const std::optional<CodeK>& code = std::nullopt);
void print_pairing(std::FILE* out, const Kernel& kernel, const Lattice& lattice, const PairingRequest& request,
                   const std::vector<PairingPoint>& points, const std::optional<CodeK>& code = std::nullopt);

} // namespace sphkern
