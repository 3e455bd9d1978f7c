// How a particle set is relaxed (share/docs/method.md section 12): the SPH pressure force
// with a velocity damping, integrated kick-drift-kick, or particle shifting along the
// gradient of sum_j V_j W_ij; and when to stop. Units: lengths in the set's spacing d (a
// lattice's, else the mean spacing V^(1/D)), speeds in the sound speed c, times in d/c.
#pragma once

#include <string>

namespace sphkern {

enum class RelaxMethod { pressure, shift };
const char* relax_method_name(RelaxMethod method);

// Checked by requests/relax_request.hpp (the engine takes them as given).
struct RelaxSettings {
    RelaxMethod method = RelaxMethod::pressure;
    int steps = 200;      // at most this many steps
    double tolerance = 0; // stop once the RMS displacement of a step is below tolerance * h (0: never)
    // pressure: P = rho0 c^2 / gamma (rho / rho0)^gamma, the model of `stability`.
    double gamma = 5.0 / 3.0;
    double time_step = 0.2; // in h / c
    double damping = 0.5;   // dv/dt = a - damping (c / h) v
    // shift: dx_i = -alpha h^2 sum_j V_j grad_i W_ij, at most max_move * h a step.
    double alpha = 0.1;
    double max_move = 0.1;
    int threads = 0; // 0: every core
    // Settled: stop once the RMS e0 of the last settle_steps + 1 steps spans less than
    // settle_change of its largest (0: never). The glass's errors then no longer move.
    int settle_steps = 0;
    double settle_change = 0.01;
};

} // namespace sphkern
