// How glass-like a periodic particle set is: the radial distribution function g(r) (a glass
// has no lattice peaks), the distances to the nearest neighbour, and the fraction of
// particles whose nearest neighbour is closer than half the mean spacing ("paired").
#pragma once

#include "particles/particle_set.hpp"
#include "particles/particle_statistics.hpp"
#include "support/text/value_checks.hpp"

#include <vector>

namespace sphkern {

struct RadialDistribution {
    double bin_width = 0;        // in units of the mean spacing l = V^(1/D)
    std::vector<double> r, g;    // bin centres (units of l) and g(r)
    double peak = 0, peak_r = 0; // the largest g and where
};

struct GlassQuality {
    RadialDistribution rdf;
    Summary nearest;             // nearest-neighbour distance, in units of l
    Histogram nearest_histogram; // 30 bins over the distances' range
    double paired = 0;           // fraction with the nearest neighbour closer than 0.5 l
};

// The nearest-neighbour distance of every particle (minimum image), in the set's units.
// Throws Error(input) for a particle with no neighbour within half the box's width.
std::vector<double> nearest_distances(const ParticleSet& set, int threads);

// The fraction of particles whose nearest neighbour is closer than 0.5 l.
double paired_fraction(const ParticleSet& set, int threads);

// g(r)'s range (finite, above 0.5 l) and bins (1 to 100000), each refusal naming its source.
void check_rdf_settings(double r_max, std::size_t bins, const ValueSource& r_max_source,
                        const ValueSource& bins_source);

// g(r) up to `r_max` (units of l; at most half the box's smallest width) in `bins` bins.
GlassQuality glass_quality(const ParticleSet& set, double r_max, std::size_t bins, int threads);

} // namespace sphkern
