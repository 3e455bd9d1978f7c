// The text `sphkern stability` prints: run_stability's result, for the request's mode (the
// modes at a wave vector, a path, the zone scan with the long waves, or k by k).
#pragma once

#include "lattices/lattice.hpp"
#include "requests/stability_request.hpp"

#include <string>

namespace sphkern {

void print_stability(const StabilityResult& result, const StabilityRequest& request, const std::string& kernel,
                     const Lattice& lattice);

} // namespace sphkern
