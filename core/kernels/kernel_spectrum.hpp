// A kernel's Fourier spectrum W^(kh) on kh = kappa h in [0, 50]: the curve, its minimum
// and the first zero. Where W^ < 0, SPH with many neighbours is unstable to pairing
// (Dehnen & Aly 2012); see the method document, section "Linear stability".
#pragma once

#include "kernels/kernel.hpp"

#include <optional>
#include <vector>

namespace sphkern {

inline constexpr double spectrum_kh_max = 50;

struct SpectrumSummary {
    int dimension = 0;
    double minimum = 0;               // min of W^ over [0, spectrum_kh_max]
    double at = 0;                    // kh of the minimum
    std::optional<double> first_zero; // the smallest kh with W^ = 0, if any
    bool provided = false;            // the plugin's own transform (else quadrature)
};

// W^ at n + 1 equally spaced kh in [0, kh_max].
std::vector<std::pair<double, double>> spectrum_curve(const Kernel& kernel, int dim, double k, double kh_max, int n);

SpectrumSummary spectrum_summary(const Kernel& kernel, int dim, double k);

} // namespace sphkern
