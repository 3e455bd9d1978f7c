// One pairing run (`sphkern pairing`): a k or a range of k, the noise, the motion's settings;
// each value checked once and named as the front end names it.
#pragma once

#include "relax/pairing_motion.hpp"
#include "support/text/value_checks.hpp"

namespace sphkern {

struct PairingSources {
    ValueSource k_min, k_max, samples, noise, duration, damping, dt, gamma, horizon, threads;
};
PairingSources pairing_sources(FrontEnd front_end);

void check_pairing_request(const PairingRequest& request, const PairingSources& sources);

} // namespace sphkern
