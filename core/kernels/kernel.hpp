// A kernel ready to evaluate: a definition plus values for its parameters. Evaluates
// the formula as written; truncation at the support R is the caller's choice.
#pragma once

#include "kernels/kernel_definition.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sphkern {

// A neighbour exactly on the support edge is inside: q <= R (1 + support_edge), so that
// rounding (a shell at 3.0000000000000004 d) cannot drop it.
inline constexpr double support_edge = 1e-12;

class Kernel {
public:
    // `values` overrides parameter defaults by name; unknown names and values out of
    // the declared range throw Error(input).
    explicit Kernel(std::shared_ptr<const KernelDefinition> definition,
                    const std::map<std::string, double>& values = {});

    const KernelDefinition& definition() const { return *definition_; }
    const std::shared_ptr<const KernelDefinition>& shared_definition() const { return definition_; }
    const std::string& name() const { return definition_->name; }
    double support() const { return definition_->support; }
    bool supports(int dim) const { return definition_->supports(dim); }
    // Throws Error(input) unless the kernel is defined in `dim` dimensions.
    void require_dimension(int dim, const std::string& lattice_name) const;
    const std::vector<double>& parameter_values() const { return values_; }

    // h^D W(q) and h^(D+1) dW/dr (q), the plugin's formulas for any q >= 0.
    double w(double q, int dim, double k) const { return f_->w(q, dim, k, values_.data()); }
    double dw(double q, int dim, double k) const { return f_->dw(q, dim, k, values_.data()); }
    void w_batch(const double* q, double* out, std::size_t n, int dim, double k) const
    {
        f_->w_batch(q, out, n, dim, k, values_.data());
    }
    void dw_batch(const double* q, double* out, std::size_t n, int dim, double k) const
    {
        f_->dw_batch(q, out, n, dim, k, values_.data());
    }
    // w_batch and dw_batch in one call (one loop in plugins that give the fused extension).
    void w_dw_batch(const double* q, double* w, double* dw, std::size_t n, int dim, double k) const
    {
        f_->w_dw_batch(q, w, dw, n, dim, k, values_.data());
    }

    // h^(D+2) d2W/dr2 (q): the plugin's formula, else a one- or two-sided finite
    // difference of dw that never straddles a breakpoint (kernels/second_derivative.cpp).
    double d2w(double q, int dim, double k) const;
    bool provides_second_derivative() const { return f_->has_second_derivative(); }

    // The Fourier transform of the truncated kernel at kh = kappa h (1 at kh = 0): the
    // plugin's formula, else a radial quadrature (kernels/fourier_transform.cpp).
    double fourier(double kh, int dim, double k) const;
    bool provides_fourier_transform() const { return f_->has_fourier_transform(); }

    // Truncated at R: zero for q > R (1 + support_edge).
    bool inside(double q) const { return q <= support() * (1 + support_edge); }
    double w_truncated(double q, int dim, double k) const { return inside(q) ? w(q, dim, k) : 0.0; }
    double dw_truncated(double q, int dim, double k) const { return inside(q) ? dw(q, dim, k) : 0.0; }

    // "name" or "name(a=0.3)" for reports.
    std::string label() const;

private:
    std::shared_ptr<const KernelDefinition> definition_;
    const KernelFunctions* f_;
    std::vector<double> values_;
};

} // namespace sphkern
