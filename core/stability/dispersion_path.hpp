// Dispersion curves: omega^2 of every branch along the high-symmetry path of the
// lattice's Brillouin zone (Γ-X-M-Γ-R for sc, Γ-X-W-L-Γ-K for fcc, ...).
#pragma once

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"

#include <string>
#include <vector>

namespace sphkern {

struct DispersionPath {
    std::vector<std::string> labels;         // the symmetry points, in path order
    std::vector<double> label_positions;     // their distance along the path, in 1/d
    std::vector<double> position;            // of every sample, in 1/d
    std::vector<std::vector<double>> omega2; // [sample][branch], ascending per sample
};

// About `points` samples, spread over the segments by length (each segment's ends included).
DispersionPath dispersion_along_path(const Dispersion& dispersion, const ReciprocalLattice& reciprocal, int points);

} // namespace sphkern
