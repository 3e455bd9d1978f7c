// The pairing instability in motion: a lattice block disturbed by small noise, moved by the
// SPH pressure force (relax --method pressure), against the linear verdict of section 10 at
// the same k. Where the lattice is stable the particles return to their sites; where a mode
// grows faster than the run lasts, the displacements grow (and pair up for a longitudinal mode).
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "stability/stability_scan.hpp"

#include <string>
#include <vector>

namespace sphkern {

struct PairingRequest {
    double k_min = 1, k_max = 1;
    int samples = 1;                   // evenly spaced k over [k_min, k_max]
    double noise = 1e-3;               // Gaussian displacement per axis, in d
    double duration = default_horizon; // in d / c
    double damping = 0.1;              // in c / h
    double time_step = 0.2;            // in h / c
    double gamma = 5.0 / 3.0;
    double horizon = default_horizon;
    unsigned long long seed = 1;
    int threads = 0;
};

struct PairingPoint {
    double k = 0;
    int cells = 0; // of the block along each axis
    std::size_t particles = 0;
    // The linear answer.
    Verdict verdict = Verdict::stable;
    double omega2 = 0;         // the lowest omega^2 over the zone, c^2 / d^2
    double growth_time = 0;    // 1 / sqrt(-omega2), d / c; infinite when stable
    std::string kind;          // of the fastest mode: longitudinal, transverse, optical ("" when stable)
    double predicted_rate = 0; // of the damped motion, -b/2 + sqrt(b^2/4 - omega2), c / d (0 when stable)
    double predicted_factor =
        0; // the linear RMS displacement at the end over the start, every block mode damped or grown
    // The motion.
    double rms_start = 0, rms_end = 0, rms_max = 0; // displacement from the sites, d
    double paired_start = 0, paired_end = 0;
    double measured_rate = 0; // fitted where the RMS displacement grew from 3x its start to 0.05 d; 0 if it did not
    std::string outcome;      // returned, held, grew, paired
    std::string expected;     // returned, grew or paired, from predicted_factor ("either": too little change to tell)
    bool agrees = false;
};

// The request as checked by requests/pairing_request.hpp. Throws Error(input) for a lattice that is not an
// SPH equilibrium (as `stability` does).
std::vector<PairingPoint> pairing_motion(const Kernel& kernel, const Lattice& lattice, const PairingRequest& request);

} // namespace sphkern
