#include "analysis/hydrostatic_errors.hpp"

#include "kernels/kernel_validity.hpp"
#include "support/error.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sphkern {

std::vector<Shell> select_shells(const std::vector<Shell>& all, const std::vector<double>& radii,
                                 const std::string& lattice_name)
{
    std::vector<Shell> chosen;
    for (double r : radii) {
        auto it = std::find_if(all.begin(), all.end(), [&](const Shell& s) { return std::abs(s.radius - r) < 1e-6; });
        if (it == all.end()) {
            std::ostringstream s;
            s.precision(10);
            s << "lattice " << lattice_name << " has no neighbour shell at radius " << r << " d";
            auto nearest = std::min_element(all.begin(), all.end(), [&](const Shell& a, const Shell& b) {
                return std::abs(a.radius - r) < std::abs(b.radius - r);
            });
            if (nearest != all.end()) s << " (nearest: " << nearest->radius << " d)";
            fail_input(s.str());
        }
        if (std::none_of(chosen.begin(), chosen.end(), [&](const Shell& c) { return c.radius == it->radius; }))
            chosen.push_back(*it);
    }
    std::sort(chosen.begin(), chosen.end(), [](const Shell& a, const Shell& b) { return a.radius < b.radius; });
    return chosen;
}

HydrostaticErrors::HydrostaticErrors(const Kernel& kernel, const Lattice& lattice, int site, double a_p,
                                     const Eigen::Vector3d& gravity, double k_max, const EvaluationMode& mode)
    : kernel_(kernel), site_(site), dim_(lattice.dimension), a_p_(a_p), gravity_(gravity.stableNormalized()),
      mode_(mode)
{
    kernel.require_dimension(lattice.dimension, lattice.name);
    require_usable_kernel(kernel, dim_, k_max);
    double reach = kernel.support() * k_max;
    if (mode.shell_radii)
        for (double r : *mode.shell_radii) reach = std::max(reach, r + 1e-6);
    all_shells_ = lattice_shells(lattice, site, reach);
    terms_ = mode.shell_radii ? select_shells(all_shells_, *mode.shell_radii, lattice.name) : all_shells_;
    for (const auto& t : terms_) moment_along_gravity_.push_back(t.moment * gravity_);
}

std::size_t HydrostaticErrors::active_terms(double k) const
{
    if (mode_.continue_past_support) return terms_.size();
    double reach = kernel_.support() * k * (1 + support_edge);
    std::size_t n = 0;
    while (n < terms_.size() && terms_[n].radius <= reach) ++n;
    return n;
}

std::vector<double> HydrostaticErrors::breakpoints(double k_min, double k_max) const
{
    std::vector<double> ks;
    if (mode_.continue_past_support) return ks;
    // Where a shell crosses a support: R, or the support of each part of a blend.
    for (double cut : kernel_.definition().truncations)
        for (const auto& t : terms_) {
            double k = t.radius / cut;
            if (k > k_min && k < k_max) ks.push_back(k);
        }
    std::sort(ks.begin(), ks.end());
    ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
    return ks;
}

ErrorValues HydrostaticErrors::at_piece(double k, std::size_t active) const
{
    const double kd = std::pow(k, dim_);
    double density = kernel_.w(0.0, dim_, k);
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (std::size_t s = 0; s < active; ++s) {
        const Shell& t = terms_[s];
        double q = t.radius / k;
        density += t.count * kernel_.w(q, dim_, k);
        gradient += (t.radius * kernel_.dw(q, dim_, k)) * moment_along_gravity_[s];
    }
    gradient *= -a_p_ / (kd * k);
    if (!std::isfinite(density) || !gradient.allFinite()) fail_non_finite(k, active);
    ErrorValues v;
    v.eps_rho = a_p_ * density / kd - 1.0;
    double along = gradient.dot(gravity_);
    v.eps_gradp = along - 1.0;
    v.lateral = (gradient - along * gravity_).norm();
    if (!std::isfinite(v.eps_rho) || !std::isfinite(v.eps_gradp) || !std::isfinite(v.lateral)) {
        std::vector<double> qs;
        for (std::size_t s = 0; s < active; ++s) qs.push_back(terms_[s].radius / k);
        fail_overflowing_kernel(kernel_, dim_, k, "the lattice's density and gradient sums", qs);
        fail_input(fmt::format("k = {:.6g} is outside what this kernel and lattice can be evaluated at: the errors "
                               "are not finite numbers (expected k of order 1)",
                               k));
    }
    double reach = kernel_.support() * k * (1 + support_edge);
    for (const auto& s : all_shells_)
        if (s.radius <= reach) v.neighbours += s.count;
    return v;
}

GradientTensor HydrostaticErrors::tensor(double k) const
{
    const std::size_t active = active_terms(k);
    const double scale = a_p_ / (std::pow(k, dim_) * k);
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    for (std::size_t s = 0; s < active; ++s) {
        const Shell& t = terms_[s];
        const double dw = kernel_.dw(t.radius / k, dim_, k);
        sum += (t.radius * dw) * t.moment;
        first += dw * t.first;
    }
    GradientTensor g;
    g.tensor.setZero();
    g.tensor.topLeftCorner(dim_, dim_) = -scale * sum.topLeftCorner(dim_, dim_) - Eigen::MatrixXd::Identity(dim_, dim_);
    g.first_moment = scale * first;
    if (!g.tensor.allFinite() || !g.first_moment.allFinite()) fail_non_finite(k, active);
    // Closed-form eigenvalues of the fixed-size block: this runs at every k a verdict samples.
    if (dim_ == 2) {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver;
        solver.computeDirect(g.tensor.topLeftCorner<2, 2>().eval(), Eigen::EigenvaluesOnly);
        g.eigenvalues = {solver.eigenvalues()[0], solver.eigenvalues()[1]};
    } else {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(g.tensor, Eigen::EigenvaluesOnly);
        g.eigenvalues = {solver.eigenvalues()[0], solver.eigenvalues()[1], solver.eigenvalues()[2]};
    }
    return g;
}

double GradientTensor::max_abs_eigenvalue() const
{
    double m = 0;
    for (double e : eigenvalues) m = std::max(m, std::abs(e));
    return m;
}

void HydrostaticErrors::fail_non_finite(double k, std::size_t active) const
{
    if (!std::isfinite(kernel_.w(0.0, dim_, k))) fail_non_finite_kernel(kernel_, "W", 0.0, dim_, k);
    for (std::size_t s = 0; s < active; ++s) {
        double q = terms_[s].radius / k;
        if (!std::isfinite(kernel_.w(q, dim_, k))) fail_non_finite_kernel(kernel_, "W", q, dim_, k);
        if (!std::isfinite(kernel_.dw(q, dim_, k))) fail_non_finite_kernel(kernel_, "dW/dr", q, dim_, k);
    }
    std::vector<double> qs;
    for (std::size_t s = 0; s < active; ++s) qs.push_back(terms_[s].radius / k);
    fail_overflowing_kernel(kernel_, dim_, k, "the lattice's density and gradient sums", qs);
    fail_input(fmt::format("k = {:.6g} is outside what this kernel and lattice can be evaluated at: the sums "
                           "overflow (expected k of order 1)",
                           k));
}

std::pair<double, double> HydrostaticErrors::shell_contribution(const Shell& shell, double k) const
{
    const double kd = std::pow(k, dim_);
    double q = shell.radius / k;
    return {a_p_ * shell.count * kernel_.w(q, dim_, k) / kd,
            -a_p_ * shell.radius * kernel_.dw(q, dim_, k) * shell.directional_moment(gravity_) / (kd * k)};
}

} // namespace sphkern
