// What kind of motion a mode is: longitudinal (particles move along the wave vector and
// pair up), transverse, or optical (the sublattices of a several-site lattice move against
// each other). A cell with several sites that is a supercell of a Bravais lattice (bcc given
// as a cubic cell) has folded branches: the mode is judged at its unfolded wave vector
// kappa + G, the G of the cell's reciprocal lattice for which the sites move most nearly in
// phase. Sublattices that are no translates of each other (hcp) are judged at kappa.
#pragma once

#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"

#include <Eigen/Core>

#include <string>

namespace sphkern {

enum class ModeKind { longitudinal, transverse, optical };
std::string mode_kind_name(ModeKind kind); // "longitudinal", "transverse", "optical"

struct ModeCharacter {
    ModeKind kind = ModeKind::transverse;
    Eigen::Vector3d unfolded = Eigen::Vector3d::Zero(); // kappa + G, in 1/d
    double in_phase = 1;     // |sum_s xi_s exp(-i G.x_s)|^2 / (sites sum_s |xi_s|^2): 1 acoustic, 0 optical
    double longitudinal = 0; // |q^ . v|^2 / |v|^2 of the in-phase motion v along q = kappa + G
};

// The mode of `branch` at kappa; optical when in_phase < 1/2, else longitudinal when
// longitudinal > 1/2, else transverse.
ModeCharacter mode_character(const Dispersion& dispersion, const ReciprocalLattice& reciprocal,
                             const Eigen::Vector3d& kappa, int branch);

} // namespace sphkern
