// One pairing run (`sphkern pairing`): a k or a range of k, the noise, the motion's settings;
// each value checked once and named as the front end names it.
#pragma once

#include "relax/pairing_motion.hpp"
#include "requests/code_setting.hpp"
#include "support/text/value_checks.hpp"

namespace sphkern {

struct PairingSources {
    ValueSource k_min, k_max, samples, noise, duration, damping, dt, gamma, horizon, threads;
};
PairingSources pairing_sources(FrontEnd front_end);

void check_pairing_request(const PairingRequest& request, const PairingSources& sources);

// With a code's setting (checked): its k on the lattice (from the bulk's SPH density at site 0
// with the Voronoi a_p), made the request's one k and checked as --k would be.
std::optional<CodeK> pairing_code_k(PairingRequest& request, const std::optional<CodeSetting>& setting,
                                    const CodeSettingSources& sources, const Kernel& kernel, const Lattice& lattice);

} // namespace sphkern
