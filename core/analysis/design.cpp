#include "analysis/design.hpp"

#include "analysis/roots.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/process/parallel_for.hpp"

#include <Eigen/SVD>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace sphkern {

namespace {

constexpr double verified = 1e-9; // both errors at a reported solution

Kernel with_parameter(const Kernel& kernel, const std::string& name, double value)
{
    std::map<std::string, double> values;
    const auto& params = kernel.definition().parameters;
    for (std::size_t i = 0; i < params.size(); ++i) values[params[i].name] = kernel.parameter_values()[i];
    values[name] = value;
    return Kernel(kernel.shared_definition(), values);
}

ErrorValues errors_at(const Kernel& kernel, const DesignProblem& p, double a_p, double k, double value)
{
    Kernel designed = with_parameter(kernel, p.parameter, value);
    HydrostaticErrors errors(designed, *p.lattice, p.site, a_p, p.gravity, std::max(k, p.k_max));
    return errors.at(k);
}

struct NewtonPoint {
    Eigen::Vector2d x;
    Eigen::Matrix2d jacobian;
};

// Newton's method on (eps_rho, eps_gradP) = 0 in (k, parameter), with a central-difference
// Jacobian; returns the converged point and the Jacobian there.
std::optional<NewtonPoint> newton(const Kernel& kernel, const DesignProblem& p, double a_p, Eigen::Vector2d x)
{
    auto residual = [&](const Eigen::Vector2d& v) {
        auto e = errors_at(kernel, p, a_p, v[0], v[1]);
        return Eigen::Vector2d(e.eps_rho, e.eps_gradp);
    };
    const double scale = std::max(1.0, std::abs(p.parameter_max - p.parameter_min));
    Eigen::Matrix2d jacobian;
    for (int iteration = 0; iteration < 40; ++iteration) {
        throw_if_interrupted();
        Eigen::Vector2d f = residual(x);
        if (!f.allFinite()) return std::nullopt;
        const double hk = 1e-7 * x[0], hp = 1e-7 * scale;
        jacobian.col(0) = (residual(x + Eigen::Vector2d(hk, 0)) - residual(x - Eigen::Vector2d(hk, 0))) / (2 * hk);
        jacobian.col(1) = (residual(x + Eigen::Vector2d(0, hp)) - residual(x - Eigen::Vector2d(0, hp))) / (2 * hp);
        if (f.norm() < 1e-14) return NewtonPoint{x, jacobian};
        Eigen::Vector2d step = jacobian.colPivHouseholderQr().solve(-f);
        if (!step.allFinite()) return std::nullopt;
        // Backtracking: halve the step until the residual shrinks (errors jump at breakpoints).
        double factor = 1;
        Eigen::Vector2d next = x + step;
        for (int halving = 0; halving < 30; ++halving, factor *= 0.5) {
            next = x + factor * step;
            if (next[0] > 0) {
                Eigen::Vector2d g = residual(next);
                if (g.allFinite() && g.norm() < f.norm()) break;
            }
        }
        x = next;
        if (x[0] <= 0) return std::nullopt;
    }
    return residual(x).norm() < verified ? std::optional(NewtonPoint{x, jacobian}) : std::nullopt;
}

// Roots of a function that is smooth on each piece between `edges`, by sampling and
// TOMS 748 (the same bracketing as the root finder of the bulk errors).
std::vector<double> piecewise_roots(const std::function<double(double, double)>& f, const std::vector<double>& edges,
                                    int samples)
{
    std::vector<double> roots;
    const double span = edges.back() - edges.front();
    for (std::size_t piece = 0; piece + 1 < edges.size(); ++piece) {
        const double a = edges[piece], b = edges[piece + 1], mid = 0.5 * (a + b);
        auto g = [&](double k) { return f(k, mid); };
        int n = std::max(8, static_cast<int>(std::ceil(samples * (b - a) / span)));
        double k0 = a, g0 = g(a);
        for (int i = 1; i <= n; ++i) {
            throw_if_interrupted();
            double k1 = a + (b - a) * i / n, g1 = g(k1);
            if (std::isfinite(g0) && std::isfinite(g1) && g0 != 0 && std::signbit(g0) != std::signbit(g1)) {
                std::uintmax_t iterations = 200;
                auto r = boost::math::tools::toms748_solve(
                    g, k0, k1, g0, g1, [](double lo, double hi) { return hi - lo <= root_tolerance; }, iterations);
                roots.push_back(0.5 * (r.first + r.second));
            } else if (g1 == 0) {
                roots.push_back(k1);
            }
            k0 = k1;
            g0 = g1;
        }
    }
    return roots;
}

std::vector<std::pair<double, double>> solve_blend(const Kernel& blend, const DesignProblem& p, double a_p)
{
    // eps(alpha) = (1 - alpha) eps_A + alpha eps_B at fixed k, so both vanish where
    // D(k) = rho_A gradP_B - rho_B gradP_A = 0, at alpha = rho_A / (rho_A - rho_B).
    const Kernel a = with_parameter(blend, "alpha", 0.0), b = with_parameter(blend, "alpha", 1.0);
    HydrostaticErrors ea(a, *p.lattice, p.site, a_p, p.gravity, p.k_max),
        eb(b, *p.lattice, p.site, a_p, p.gravity, p.k_max);
    std::vector<double> edges = {p.k_min};
    for (double k : ea.breakpoints(p.k_min, p.k_max)) edges.push_back(k);
    edges.push_back(p.k_max);
    auto determinant = [&](double k, double mid) {
        auto va = ea.at_piece(k, ea.active_terms(mid)), vb = eb.at_piece(k, eb.active_terms(mid));
        return va.eps_rho * vb.eps_gradp - vb.eps_rho * va.eps_gradp;
    };
    std::vector<std::pair<double, double>> found;
    for (double k : piecewise_roots(determinant, edges, 400)) {
        auto va = ea.at(k), vb = eb.at(k);
        double rho_gap = va.eps_rho - vb.eps_rho, gradp_gap = va.eps_gradp - vb.eps_gradp;
        double alpha = std::abs(rho_gap) >= std::abs(gradp_gap) ? va.eps_rho / rho_gap : va.eps_gradp / gradp_gap;
        if (std::isfinite(alpha)) found.emplace_back(k, alpha);
    }
    return found;
}

std::vector<std::pair<double, double>> solve_by_newton(const Kernel& kernel, const DesignProblem& p, double a_p)
{
    // Along a grid of parameter values, the roots in k of each error and the other error
    // there; a sign change of the other error along one branch of roots brackets a
    // solution, which Newton's method then refines in (k, parameter).
    const int steps = 80;
    std::vector<RootScan> scans(steps + 1);
    ParallelFor pass;
    pass.run_blocks(scans.size(), 1, p.threads, [&](std::size_t b, std::size_t, std::size_t) {
        const int i = static_cast<int>(b);
        double value = p.parameter_min + (p.parameter_max - p.parameter_min) * i / steps;
        HydrostaticErrors errors(with_parameter(kernel, p.parameter, value), *p.lattice, p.site, a_p, p.gravity,
                                 p.k_max);
        scans[b] = find_roots(errors, p.k_min, p.k_max, 200);
    });
    std::vector<std::pair<double, double>> found;
    for (auto function : {ErrorFunction::rho, ErrorFunction::gradp}) {
        auto other = [&](const Root& r) {
            return function == ErrorFunction::rho ? r.values.eps_gradp : r.values.eps_rho;
        };
        for (int i = 0; i < steps; ++i)
            for (const auto& r0 : scans[static_cast<std::size_t>(i)].roots) {
                if (r0.function != function) continue;
                const Root* r1 = nullptr; // the same branch one step on: the nearest root in k
                for (const auto& r : scans[static_cast<std::size_t>(i + 1)].roots)
                    if (r.function == function && (!r1 || std::abs(r.k - r0.k) < std::abs(r1->k - r0.k))) r1 = &r;
                if (!r1 || std::abs(r1->k - r0.k) > 0.05) continue;
                double g0 = other(r0), g1 = other(*r1);
                if (std::signbit(g0) == std::signbit(g1)) continue;
                double t = g0 / (g0 - g1);
                double v0 = p.parameter_min + (p.parameter_max - p.parameter_min) * i / steps;
                double v1 = p.parameter_min + (p.parameter_max - p.parameter_min) * (i + 1) / steps;
                Eigen::Vector2d guess(r0.k + t * (r1->k - r0.k), v0 + t * (v1 - v0));
                if (auto solution = newton(kernel, p, a_p, guess)) found.emplace_back(solution->x[0], solution->x[1]);
            }
    }
    return found;
}

std::vector<std::pair<double, double>> solve(const Kernel& kernel, const DesignProblem& p, bool blend)
{
    auto found = blend ? solve_blend(kernel, p, p.a_p) : solve_by_newton(kernel, p, p.a_p);
    std::vector<std::pair<double, double>> kept;
    for (const auto& solution : found) {
        const double k = solution.first, value = solution.second;
        if (k < p.k_min || k > p.k_max || value < p.parameter_min || value > p.parameter_max) continue;
        bool duplicate = std::any_of(kept.begin(), kept.end(), [&](const auto& s) {
            return std::abs(s.first - k) < 1e-7 && std::abs(s.second - value) < 1e-7 * std::max(1.0, std::abs(value));
        });
        if (!duplicate) kept.emplace_back(k, value);
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

} // namespace

std::pair<double, double> default_parameter_range(const Kernel& kernel, const std::string& parameter)
{
    if (parameter == "alpha" && kernel.name().find('+') != std::string::npos) return {-1, 2};
    for (const auto& p : kernel.definition().parameters)
        if (p.name == parameter) return {p.min_value, p.max_value};
    return {0, 1}; // an unknown parameter: design_kernel names the known ones
}

void check_design_parameter(const Kernel& kernel, const std::string& parameter, double min, double max)
{
    const auto& params = kernel.definition().parameters;
    auto declared = std::find_if(params.begin(), params.end(), [&](const auto& q) { return q.name == parameter; });
    if (declared == params.end()) {
        std::string list;
        for (const auto& q : params) list += (list.empty() ? "" : ", ") + q.name;
        fail_input("kernel " + kernel.name() + " has no parameter \"" + parameter + "\"" +
                   (list.empty() ? "; it has no parameters (a blend A+B has alpha)" : "; it has: " + list));
    }
    if (!(min < max) || min < declared->min_value || max > declared->max_value) {
        std::ostringstream s;
        s << "parameter range [" << min << ", " << max << "] is not allowed, expected " << declared->min_value
          << " <= min < max <= " << declared->max_value;
        fail_input(s.str());
    }
}

DesignResult design_kernel(const Kernel& kernel, const DesignProblem& p)
{
    check_design_parameter(kernel, p.parameter, p.parameter_min, p.parameter_max);
    kernel.require_dimension(p.lattice->dimension, p.lattice->name);
    const bool blend = kernel.definition().name.find('+') != std::string::npos && p.parameter == "alpha";

    DesignResult result;
    for (const auto& [k, value] : solve(kernel, p, blend)) {
        DesignSolution s;
        s.k = k;
        s.parameter = value;
        s.method = blend ? "blend" : "newton";
        s.values = errors_at(kernel, p, p.a_p, k, value);
        if (std::abs(s.values.eps_rho) > verified || std::abs(s.values.eps_gradp) > verified) continue;
        // The Jacobian J at the solution gives its condition and, since both errors are
        // a_p S - 1 with S fixed, the first-order move when a_p grows by 1%: both errors
        // grow by 0.01, so (dk, dparameter) = -J^-1 (0.01, 0.01).
        if (auto refined = newton(kernel, p, p.a_p, Eigen::Vector2d(k, value))) {
            Eigen::JacobiSVD<Eigen::Matrix2d> svd(refined->jacobian);
            s.jacobian_condition = svd.singularValues()[0] / svd.singularValues()[1];
            Eigen::Vector2d move = refined->jacobian.colPivHouseholderQr().solve(-Eigen::Vector2d(0.01, 0.01));
            s.k_shift = move[0];
            s.parameter_shift = move[1];
        } else {
            s.jacobian_condition = s.k_shift = s.parameter_shift = NAN;
        }
        Kernel designed = with_parameter(kernel, p.parameter, value);
        for (int i = 0; i <= 2000; ++i)
            s.non_negative = s.non_negative && designed.w(designed.support() * i / 2000, p.lattice->dimension, k) >= 0;
        result.solutions.push_back(s);
    }
    if (result.solutions.empty()) {
        std::ostringstream note;
        note << "no (k, " << p.parameter << ") with k in [" << p.k_min << ", " << p.k_max << "] and " << p.parameter
             << " in [" << p.parameter_min << ", " << p.parameter_max << "] where both errors vanish";
        result.note = note.str();
    }
    return result;
}

} // namespace sphkern
