// A relaxation run: a particle set in its periodic box moved step by step by one of the
// methods of RelaxSettings until the stopping rule holds, with a history of every step.
#pragma once

#include "support/error.hpp"

#include "kernels/kernel.hpp"
#include "particles/particle_set.hpp"
#include "relax/relax_settings.hpp"
#include "relax/sph_forces.hpp"

#include <functional>
#include <string>
#include <vector>

namespace sphkern {

// One step: how far particles moved in it (in units of h), the consistency errors after it
// (RMS of e0 = sum_j V W_ij - 1 and of |e1| = h |sum_j V grad W_ij|) and, for `pressure`,
// the kinetic energy per particle (in units of c^2, unit mass).
struct RelaxStep {
    int step = 0;
    double time = 0; // in d / c
    double rms_move = 0, max_move = 0;
    double rms_e0 = 0, rms_e1 = 0;
    double kinetic = 0;
};

// The state a step leaves: positions (in the set), velocities (pressure) and each
// particle's displacement since the start, not wrapped into the box (units of d).
struct RelaxState {
    ParticleSet set;
    std::vector<double> vx, vy, vz;
    std::vector<double> ux, uy, uz;
    ForceField forces;
    ForceModel model;
    KeptPairs pairs; // the forces' pair list, kept from step to step while it holds
};

struct RelaxResult {
    RelaxState state;
    std::vector<RelaxStep> history; // step 0 (the start) and every step taken
    double spacing = 1;             // d: the set's, else the mean spacing
    double h = 1;
    double dt = 0;    // in d / c (pressure)
    std::string stop; // why it stopped: "tolerance", "settled" or "steps"
    // Seconds of the start (its first sums), and over the steps of the grid, the density and
    // force passes, and the rest (kicks, moves, wrapping, each step's errors).
    PhaseTimes phases;
};

// A relaxation stopped because its integration diverged (a move not finite, or longer than a
// quarter of the box in one step): the message names the step, the time and the settings to
// change; `history` holds the steps before it, all finite (what is safe to write).
class RelaxDiverged : public Error {
public:
    RelaxDiverged(const std::string& message, std::vector<RelaxStep> steps)
        : Error(ExitCode::input, message), history(std::move(steps))
    {}
    std::vector<RelaxStep> history;
};

// Relaxes `set` (which needs a periodic box) at one h for every particle. `observe` is called
// after step 0 and every step. Throws Error(input) for settings out of range, a set without
// a box and an h whose support does not fit twice into the box, and RelaxDiverged.
RelaxResult relax_particles(const Kernel& kernel, ParticleSet set, double h, const RelaxSettings& settings,
                            const std::function<void(const RelaxState&, const RelaxStep&)>& observe = {});

// The length unit d of a set: its lattice spacing, else the mean spacing V^(1/D).
double length_unit(const ParticleSet& set);

} // namespace sphkern
