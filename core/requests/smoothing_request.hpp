// How h is given, for every request on a particle set (particles, relax, a study's sources):
// eta, N_H, k, or the file's own h under a convention; each value checked once, named as
// the front end names it.
#pragma once

#include "particles/particle_set.hpp"
#include "particles/smoothing_lengths.hpp"
#include "support/text/value_checks.hpp"

#include <optional>

namespace sphkern {

struct SmoothingArguments {
    std::optional<double> eta, nh, k;
    std::optional<double> support_per_h; // a file's h: the support radius over the stored h
};

struct SmoothingSources {
    ValueSource eta, nh, k, support_per_h;
    ValueSource code; // the code whose convention a file's h is read in; unnamed where there is none
};
SmoothingSources smoothing_sources(FrontEnd front_end);

// At most one of eta, N_H and k (none: `fallback`), in range: eta (0, 100], N_H [1, 1e5], k (0, 100].
SmoothingSpec smoothing_spec(const SmoothingArguments& given, const SmoothingSources& sources,
                             SmoothingSpec fallback = {SmoothingRule::eta, 1.2, 0});

// A k only on a lattice; a file's h only where the file has h and its convention is known.
void check_smoothing_fits(const SmoothingSpec& spec, const ParticleSet& set, const SmoothingSources& sources);

// A file's h under the file's own convention (SWIFT's kernel gamma) is for the file's kernel:
// `kernel` (sphkern's name) must be that one, unless the convention is given (support_per_h).
void check_file_kernel(const SmoothingSpec& spec, const ParticleSet& set, const std::string& kernel,
                       const SmoothingSources& sources);

// The kernel a file names, as its errors quote it: "Cubic spline (M4)" (sphkern's cubic_bspline).
std::string file_kernel_text(const ParticleSet& set);

// The spec for a set: none given, the file's h where the set has h and `file_h_allowed`.
SmoothingSpec smoothing_of(const SmoothingArguments& given, const ParticleSet& set, const SmoothingSources& sources,
                           bool file_h_allowed = true);

} // namespace sphkern
