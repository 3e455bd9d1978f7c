// One spectrum request (the command line's `spectrum`): the Fourier transform of a kernel
// against kappa h, with its minimum and first zero.
#pragma once

#include "kernels/kernel.hpp"
#include "kernels/kernel_spectrum.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <utility>
#include <vector>

namespace sphkern {

struct SpectrumRequest {
    int dimension = 0;               // 1, 2 or 3
    double k = 1;                    // for kernels whose formula depends on it, in [1e-3, 100]
    double kh_max = spectrum_kh_max; // the curve's end, in [0.1, 1000]
    int points = 500;                // intervals on [0, kh_max], 1 to 100000
};

// How the front end names each value in its errors.
struct SpectrumSources {
    ValueSource dimension, k, kh_max, points;
};

// Every value that does not need the kernel; an Error naming its source.
void check_spectrum_request(const SpectrumRequest& request, const SpectrumSources& sources);

struct SpectrumResult {
    std::vector<std::pair<double, double>> curve; // (kappa h, W^), every value finite
    SpectrumSummary summary;
};

// Error(input) when the kernel lacks the dimension or its transform is not finite on the curve.
SpectrumResult run_spectrum(const SpectrumRequest& request, const SpectrumSources& sources, const Kernel& kernel);

// The document `sphkern spectrum --json` prints (without provenance and inputs).
nlohmann::json spectrum_document(const SpectrumRequest& request, const SpectrumResult& result, const Kernel& kernel);
// The text `sphkern spectrum` prints, on the results file.
void print_spectrum(const SpectrumRequest& request, const SpectrumResult& result, const Kernel& kernel);

} // namespace sphkern
