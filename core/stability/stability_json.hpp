// The JSON documents of `sphkern stability` (and the Python module), made from its results
// (stability_results.hpp): the modes at one wave vector, the Brillouin-zone scan with the
// long-wave sound speeds, stability against k and the dispersion curves along the path.
#pragma once

#include "stability/dispersion_path.hpp"
#include "stability/stability_over_k.hpp"
#include "stability/stability_results.hpp"

#include <nlohmann/json_fwd.hpp>

namespace sphkern {

// The document of each mode's result.
nlohmann::json stability_json(const WavevectorModes& result);
nlohmann::json stability_json(const ZoneScan& result);
nlohmann::json stability_json(const StabilityAgainstK& result);
nlohmann::json stability_json(const PathDispersion& result);

// One k of a scan over k; a mode's kind.
nlohmann::json stability_sample_json(const StabilitySample& sample, int dim);
nlohmann::json mode_json(const ModeCharacter& mode, int dim);

nlohmann::json dispersion_path_json(const DispersionPath& path);

} // namespace sphkern
