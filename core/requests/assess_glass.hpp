// The errors a relaxed glass shows at a recommended setting (`assess --glass N`), beside the
// lattice's: N Poisson particles in the unit box of the lattice's dimension, relaxed under the
// pressure of `stability` (one h, the setting's h over l) until settled, then measured as
// `particles` measures them, with the code's own h where it solves h from the density.
#pragma once

#include "kernels/kernel.hpp"
#include "particles/particle_statistics.hpp"
#include "requests/smoothing_request.hpp"

#include <cstddef>

namespace sphkern {

// A glass settles when the RMS e0 of its last settle_steps + 1 steps spans less than 1% of its
// largest; it is measured then, or after max_steps if it has not (and says so).
inline constexpr int glass_settle_steps = 20, glass_max_steps = 400;

struct GlassAtSetting {
    std::size_t particles = 0;
    double h_over_l = 0;
    int steps = 0;                                     // relaxation steps taken
    bool settled = false;                              // false: stopped at glass_max_steps
    Summary e0, eps_gradp;                             // over every particle (the box is periodic: no surface)
    double poisson_rms_e0 = 0;                         // the start's, at the same h
    double lattice_eps_rho = 0, lattice_eps_gradp = 0; // the lattice's at the same setting (assess fills them)
};

// `measure`: the smoothing the glass is measured with (the setting's h over l, or the code's solve).
GlassAtSetting glass_at(const Kernel& kernel, int dimension, double h_over_l, const SmoothingSpec& measure,
                        std::size_t count, double gamma, int threads);

} // namespace sphkern
