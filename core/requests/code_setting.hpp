// A code's own setting of the resolution instead of k (analysis/code_profiles): `swift`
// with its eta, `phantom` with its hfact, ...; what the requests that take one k (eps,
// surface, assess) share to check it and to find its k on a lattice.
#pragma once

#include "codes/code_profile.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "particles/smoothing_lengths.hpp"
#include "requests/evaluation_inputs.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <utility>

namespace sphkern {

struct CodeSetting {
    CodeSetting(std::string code_name = {}, double parameter = 0, std::optional<NeighbourCount> count = std::nullopt)
        : code(std::move(code_name)), value(parameter), counts(count)
    {}
    std::string code;
    double value = 0;
    // On a particle set, what the code's density solve counts where the code lets it be chosen
    // (SWIFT's SPH:use_mass_weighted_num_ngb); none: the code's default.
    std::optional<NeighbourCount> counts;
    // On a particle set, the code's density bias correction where it has one (GADGET-4's
    // WENDLAND_BIAS_CORRECTION); off by default, as in the code.
    bool bias_correction = false;
};

// How the front end names the code and its parameter ("--code", "--eta"; "code", "value").
struct CodeSettingSources {
    ValueSource code, value;
};

// A code and its parameter's value given apart (Python's code= and value=): both or neither.
std::optional<CodeSetting> code_setting_of(const std::optional<std::string>& code, std::optional<double> value,
                                           const CodeSettingSources& sources);

// A known code, and a value its parameter can take; an Error naming the source.
void check_code_setting(const CodeSetting& setting, const CodeSettingSources& sources);

// The setting's k at the evaluated site: from the lattice's own SPH density where the code
// solves for h with it, so that the code's parameter recomputed at k is the one given.
struct CodeK {
    CodeSetting setting;
    std::string parameter; // the code's name for it ("eta")
    double k = 0;
    double value_at_k = 0;     // the code's parameter recomputed at k (equal to the given to 1e-12)
    std::optional<double> a_p; // the volume the code fixes (SPlisHSPlasH), in place of the lattice's
};
CodeK k_of_code_setting(const CodeSetting& setting, const CodeSettingSources& sources, const Kernel& kernel,
                        const Lattice& lattice, const Evaluation& evaluation);

// The h of a code's setting on a particle set: h_i = c (m_i / rho_i)^(1/D) solved with each
// particle's SPH density where the code solves for h with it (SWIFT, Phantom, GADGET), else
// h = c V̄^(1/D) from the mean spacing (PySPH, DualSPHysics); c follows from the code's
// definition for `kernel` in `dimension`.
SmoothingSpec code_smoothing(const CodeSetting& setting, const CodeSettingSources& sources, const Kernel& kernel,
                             int dimension);

// A code named alone on a set that stores h: that h as the code stores it, its support radius
// code_support_per_h times it and a pair's h the code's; the kernel one the code ships and, where
// the file names its kernel, that one. Error(input) for a set without h, naming `source`'s
// parameter (`value`) as the other way.
SmoothingSpec stored_code_smoothing(const std::string& code, const CodeSettingSources& sources, const Kernel& kernel,
                                    const ParticleSet& set);

// {"name", "parameter", "value", "value_at_k"}, as `--json` carries it under "code".
nlohmann::json code_k_json(const CodeK& code);

// On a particle set: {"name", "parameter", "value", "h_from": "sph_density" or "mean_spacing"},
// and the line "swift eta = 1.2348: h from each particle's SPH density".
nlohmann::json code_answer_json(const CodeSetting& setting);
std::string code_answer_text(const CodeSetting& setting);
// A code's stored h: {"name", "parameter", "h_from": "file", "support_per_h", "pair_h": "own" or "mean"}
// and its line.
nlohmann::json stored_code_json(const std::string& code, const Kernel& kernel, int dimension);
std::string stored_code_text(const std::string& code, const Kernel& kernel, int dimension);

} // namespace sphkern
