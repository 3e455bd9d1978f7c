// The SPH sums of a relaxation step at one h for every particle: the summation density,
// the gradient of sum_j V_j W_ij, and the pressure acceleration of standard fixed-h SPH
// (the equations of share/docs/method.md section 10, for any particle set):
//   rho_i = m sum_j W_ij (own term included),   a_i = -sum_j m (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij,
// with P = rho0 c^2 / gamma (rho / rho0)^gamma. Sums run in the neighbour grid's order:
// the result does not depend on the thread count.
#pragma once

#include "support/process/phase_times.hpp"

#include "kernels/kernel.hpp"
#include "particles/engine/pair_list.hpp"
#include "particles/particle_set.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace sphkern {

struct ForceModel {
    double h = 1;      // one h for every particle (support R h)
    double volume = 1; // V of every particle: the box over N
    double mass = 1;   // m of every particle
    double rho0 = 1;   // the density at which P / rho = c^2 / gamma
    double c = 1;      // the sound speed at rho0
    double gamma = 5.0 / 3.0;
    double k = 1;         // h / d, the argument of kernels that depend on k
    bool pressure = true; // false: the density and the gradient sum only
    int threads = 1;
    // The pair list's buffer beyond the support, in h: a list kept across calls (KeptPairs)
    // holds until a particle has moved half of it.
    double skin = 0;
};

struct ForceField {
    std::vector<double> density;    // rho_i
    std::vector<double> gx, gy, gz; // sum_j V grad_i W_ij (1 / length)
    std::vector<double> ax, ay, az; // the pressure acceleration (empty without `pressure`)
    PhaseTimes phases;              // grid, density and forces, added up over every call
    double pressure(double density, const ForceModel& model) const;
};

// What calls on one set as it moves (relax's steps) keep: a pair list, used while no particle
// has moved more than half its skin since it was built, and built (again) only where the
// particles moved so little since the last call that the list would last several calls;
// elsewhere each call searches its own grid.
struct KeptPairs {
    std::shared_ptr<PairList> list;
    std::optional<MovesSince> since_last; // the positions of the last call
    int builds = 0;
};

// Throws Error(input) for two particles at one place (naming them), a box narrower than
// twice the support, and a non-finite sum (naming the particle). With `kept`, the pairs may
// come from its list (the same sums to rounding, 1e-13).
void compute_forces(const Kernel& kernel, const ParticleSet& set, const ForceModel& model, ForceField& out,
                    KeptPairs* kept = nullptr);

} // namespace sphkern
