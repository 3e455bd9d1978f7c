// The bulk relative errors of a particle at rest in a hydrostatic field (share/docs/method.md
// section 2): eps_rho(k) and eps_gradP(k) as sums over neighbour shells, plus the
// spurious lateral component of the pressure gradient. O(shells) per k.
#pragma once

#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "lattices/shells.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace sphkern {

struct EvaluationMode {
    // Evaluate one-formula kernels past q = R instead of truncating (paper-compatible).
    bool continue_past_support = false;
    // Sum over these shells only (radii in units of d) instead of every shell in the support.
    std::optional<std::vector<double>> shell_radii;
};

struct ErrorValues {
    double eps_rho = 0;
    double eps_gradp = 0;
    double lateral = 0; // |tangential part of the gradient| / (rho0 g)
    int neighbours = 0; // N_H: lattice points within the support radius, excluding the particle
};

// The gradient-error tensor E = -a_p sum_j r_j W'(r_j) r_hat r_hat^T - I of a site
// (D x D, in the top-left corner): along a unit direction e, eps_gradP(e) = e^T E e and
// the lateral error is |(I - e e^T) E e|. Its eigenvalues bound eps_gradP over every
// direction. The first moment m1 = a_p sum_j W'(r_j) r_hat_j (r_hat_j from the particle
// towards neighbour j, times d^(D+1)) is zero where the site is a centre of inversion;
// elsewhere the sum form of the gradient carries an error 2 P_i m1 that grows with depth.
struct GradientTensor {
    Eigen::Matrix3d tensor;
    std::vector<double> eigenvalues; // ascending, D of them
    Eigen::Vector3d first_moment;
    double max_abs_eigenvalue() const;
};

class HydrostaticErrors {
public:
    HydrostaticErrors(const Kernel& kernel, const Lattice& lattice, int site, double a_p,
                      const Eigen::Vector3d& gravity, double k_max, const EvaluationMode& mode = {});

    ErrorValues at(double k) const { return at_piece(k, active_terms(k)); }

    // The errors with the first `active` shell terms summed, whatever k: the smooth
    // continuation of one piece, used to bracket roots and to measure jumps.
    ErrorValues at_piece(double k, std::size_t active) const;
    std::size_t active_terms(double k) const;

    // The gradient-error tensor and the first moment at k (method of the README, "every direction").
    GradientTensor tensor(double k) const;

    // k in (k_min, k_max) where a summed shell enters the support (r = R k d).
    std::vector<double> breakpoints(double k_min, double k_max) const;

    const std::vector<Shell>& terms() const { return terms_; }
    const Kernel& kernel() const { return kernel_; }
    int site() const { return site_; }
    int dimension() const { return dim_; }

    // The contribution of one shell term to (eps_rho, eps_gradP) at k.
    std::pair<double, double> shell_contribution(const Shell& shell, double k) const;

private:
    [[noreturn]] void fail_non_finite(double k, std::size_t active) const;

    Kernel kernel_;
    int site_;
    int dim_;
    double a_p_;
    Eigen::Vector3d gravity_;
    EvaluationMode mode_;
    std::vector<Shell> all_shells_;                     // every lattice shell up to R k_max, for N_H
    std::vector<Shell> terms_;                          // the shells summed
    std::vector<Eigen::Vector3d> moment_along_gravity_; // moment * gravity per term
};

// The shells of `all` at the given radii (within 1e-6 d); throws Error(input) naming a
// radius that is not a shell.
std::vector<Shell> select_shells(const std::vector<Shell>& all, const std::vector<double>& radii,
                                 const std::string& lattice_name);

} // namespace sphkern
