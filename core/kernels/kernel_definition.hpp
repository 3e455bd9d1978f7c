// What sphkern knows of a kernel, wherever it comes from (a plugin, a blend of two
// kernels, an expression file): its metadata and its four functions.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace sphkern {

struct KernelParameter {
    std::string name;
    std::string description;
    double default_value;
    double min_value;
    double max_value;
};

// h^D W(q) and h^(D+1) dW/dr(q), scalar and batch, with the parameter values.
class KernelFunctions {
public:
    virtual ~KernelFunctions() = default;
    virtual double w(double q, int dim, double k, const double* params) const = 0;
    virtual double dw(double q, int dim, double k, const double* params) const = 0;
    virtual void w_batch(const double* q, double* out, std::size_t n, int dim, double k,
                         const double* params) const = 0;
    virtual void dw_batch(const double* q, double* out, std::size_t n, int dim, double k,
                          const double* params) const = 0;
    // W and W' together (a plugin's fused evaluation); by default the two batch calls.
    virtual void w_dw_batch(const double* q, double* w, double* dw, std::size_t n, int dim, double k,
                            const double* params) const
    {
        w_batch(q, w, n, dim, k, params);
        dw_batch(q, dw, n, dim, k, params);
    }
    // Optional: h^(D+2) d2W/dr2 and the Fourier transform as a function of kappa h. Without
    // them the Kernel computes both numerically.
    virtual bool has_second_derivative() const { return false; }
    virtual double d2w(double, int, double, const double*) const { return 0.0; }
    virtual bool has_fourier_transform() const { return false; }
    virtual double fourier_transform(double, int, double, const double*) const { return 0.0; }
};

// What made a kernel: check words its hints in the terms of that file.
enum class KernelOrigin { plugin, expression, blend };

struct KernelDefinition {
    std::string abi;    // "2.0" for a plugin, empty otherwise
    std::string source; // the plugin or expression file, or how the kernel was made
    std::string name;
    std::string title;
    std::string reference;
    double support = 0;
    std::vector<int> dimensions;
    std::vector<KernelParameter> parameters;
    std::vector<double> breakpoints;  // interior q where the definition changes
    bool separate_derivative = false; // dW/dr is its own formula
    bool from_expression = false;     // expression files only (its faults are input errors, not plugin errors)
    KernelOrigin origin = KernelOrigin::plugin;
    bool normalised = false;     // an expression file with "normalise": true: sphkern divides W by its integral
    std::string derivative_note; // how dW/dr is obtained when it is not a formula
    // q at which the kernel (or a part of it) is cut to zero: {R}, or each part's R for a blend.
    std::vector<double> truncations;
    std::shared_ptr<const KernelFunctions> functions;

    bool supports(int dim) const;
    std::string dimensions_text() const; // "1,2,3"
};

} // namespace sphkern
