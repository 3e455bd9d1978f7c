// One relaxation (`sphkern relax`, a study source's "relax"): h, the settings and the g(r)
// that judges the glass, each value checked once and named as the front end names it.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/particle_set.hpp"
#include "relax/relax_settings.hpp"
#include "requests/smoothing_request.hpp"

#include <cstddef>
#include <string>

namespace sphkern {

struct RelaxSources {
    SmoothingSources smoothing;
    ValueSource method, steps, tolerance, gamma, dt, damping, alpha, max_move, threads, rdf_max, rdf_bins;
};
RelaxSources relax_sources(FrontEnd front_end);

// pressure or shift.
RelaxMethod relax_method_of(const std::string& name, const ValueSource& source);

// Steps 1 to 1e7, tolerance [0, 1], gamma (0, 1000], dt (0, 0.5], damping [0, 100], alpha
// (0, 10], max_move (0, 0.5], threads 0 to 1024.
void check_relax_settings(const RelaxSettings& settings, const RelaxSources& sources);

// g(r) up to r_max mean spacings (above 0.5) in 1 to 100000 bins.
void check_rdf(double r_max, std::size_t bins, const RelaxSources& sources);

// The one h of a relaxation (fixed-h SPH; a file's own h is not used): the set must have a
// periodic box and fit the spec (smoothing_spec's).
double relax_h(const SmoothingSpec& spec, const ParticleSet& set, const Kernel& kernel, const SmoothingSources& sources);

} // namespace sphkern
