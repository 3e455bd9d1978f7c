#include "kernels/kernel_check.hpp"

#include "support/error.hpp"
#include "support/isolated_call.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <sstream>

namespace sphkern {

namespace {

constexpr double pi = 3.14159265358979323846;
// The k at which k-dependent formulas (a separate derivative) are checked.
constexpr double check_k = 1.0;

double sphere_area(int dim) { return dim == 1 ? 2.0 : dim == 2 ? 2 * pi : 4 * pi; }

std::string format(double v, int digits = 10)
{
    std::ostringstream s;
    s.precision(digits);
    s << v;
    return s.str();
}

struct Checks {
    nlohmann::json items = nlohmann::json::array();
    int worst = 0; // 0 ok, 1 warn, 2 fail
    void add(int dim, const std::string& name, int status, const std::string& detail)
    {
        static const char* names[] = {"ok", "warn", "fail"};
        items.push_back({{"dimension", dim}, {"check", name}, {"status", names[status]}, {"detail", detail}});
        worst = std::max(worst, status);
    }
};

std::vector<double> piece_edges(const Kernel& kernel)
{
    std::vector<double> edges = {0.0};
    for (double b : kernel.definition().breakpoints) edges.push_back(b);
    edges.push_back(kernel.support());
    return edges;
}

} // namespace

std::pair<double, double> kernel_integral(const Kernel& kernel, int dim, double k, int radial_power)
{
    double total = 0, error = 0;
    auto edges = piece_edges(kernel);
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
        double piece_error = 0;
        total += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double q) { return kernel.w(q, dim, k) * std::pow(q, dim - 1 + radial_power); }, edges[i],
            edges[i + 1], 15, 1e-15, &piece_error);
        error += piece_error;
    }
    return {sphere_area(dim) * total, sphere_area(dim) * error};
}

nlohmann::json check_kernel(const Kernel& kernel)
{
    const double R = kernel.support();
    Checks checks;
    nlohmann::json normalization = nlohmann::json::object(), second = nlohmann::json::object();
    for (int dim : kernel.definition().dimensions) {
        const std::string D = std::to_string(dim);

        // Finiteness on a grid past R and at several k.
        int bad = 0;
        double bad_q = 0;
        for (double k : {0.75, 1.0, 1.25})
            for (int i = 0; i <= 2000; ++i) {
                double q = 1.5 * R * i / 2000;
                if (!std::isfinite(kernel.w(q, dim, k)) || !std::isfinite(kernel.dw(q, dim, k))) {
                    if (!bad++) bad_q = q;
                }
            }
        checks.add(dim, "finiteness", bad ? 2 : 0,
                   bad ? std::to_string(bad) + " non-finite values, first at q = " + format(bad_q)
                       : "W and dW/dr finite on [0, 1.5 R] at k = 0.75, 1, 1.25");

        // Normalisation of the truncated kernel.
        auto [integral, error] = kernel_integral(kernel, dim, check_k);
        normalization[D] = integral;
        double deviation = std::abs(integral - 1);
        checks.add(dim, "normalization", deviation <= normalization_ok ? 0 : deviation <= normalization_warn ? 1 : 2,
                   "integral of W = " + format(integral) + " (quadrature error estimate " + format(error, 2) + ")");

        // First moment (zero for a radial kernel) and second moment (the width).
        double first = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double x) { return x * kernel.w_truncated(std::abs(x), dim, check_k); }, -R, R, 15, 1e-15);
        checks.add(dim, "first_moment", std::abs(first) <= 1e-12 ? 0 : 2,
                   "integral of x W(|x|) dx over [-R, R] = " + format(first, 3));
        double width = kernel_integral(kernel, dim, check_k, 2).first;
        second[D] = width;
        checks.add(dim, "second_moment", 0, "integral of q^2 W = " + format(width) + " (in units of h^2)");

        // Derivative against a central difference of W, away from breakpoints.
        double mismatch = 0, scale = 0, worst_q = 0;
        auto edges = piece_edges(kernel);
        for (int i = 1; i < 400; ++i) {
            double q = R * i / 400.0;
            bool near_edge = false;
            for (double e : edges) near_edge |= std::abs(q - e) < 1e-4;
            if (near_edge) continue;
            double step = 1e-6;
            double numeric = (kernel.w(q + step, dim, check_k) - kernel.w(q - step, dim, check_k)) / (2 * step);
            double supplied = kernel.dw(q, dim, check_k);
            scale = std::max(scale, std::abs(supplied));
            if (std::abs(supplied - numeric) > mismatch) {
                mismatch = std::abs(supplied - numeric);
                worst_q = q;
            }
        }
        double relative = mismatch / std::max(scale, 1e-300);
        if (!kernel.definition().derivative_note.empty())
            checks.add(dim, "derivative", 0, kernel.definition().derivative_note);
        else if (kernel.definition().separate_derivative)
            checks.add(dim, "derivative", 0,
                       "declared a separate derivative: differs from dW/dr by up to " + format(relative, 3) +
                           " (relative, at q = " + format(worst_q, 4) + ", k = 1); reported, not checked");
        else
            checks.add(dim, "derivative", relative <= 1e-6 ? 0 : 2,
                       "largest relative difference from a numerical dW/dr: " + format(relative, 3) + " at q = " +
                           format(worst_q, 4));

        // Continuity of W and dW/dr at each breakpoint and at R (where the host truncates).
        double w0 = std::abs(kernel.w(0, dim, check_k)), dw_scale = std::max(scale, 1e-300);
        for (std::size_t i = 1; i < edges.size(); ++i) {
            double b = edges[i];
            bool at_support = i + 1 == edges.size();
            double eps = 1e-9 * b;
            double w_left = kernel.w(b - eps, dim, check_k), dw_left = kernel.dw(b - eps, dim, check_k);
            double w_right = at_support ? 0.0 : kernel.w(b + eps, dim, check_k);
            double dw_right = at_support ? 0.0 : kernel.dw(b + eps, dim, check_k);
            double w_jump = std::abs(w_right - w_left), dw_jump = std::abs(dw_right - dw_left);
            std::string where = at_support ? "at R = " + format(b) : "at breakpoint q = " + format(b);
            bool w_ok = w_jump <= 1e-7 * std::max(w0, 1e-300);
            bool dw_ok = dw_jump <= 1e-7 * dw_scale;
            checks.add(dim, "continuity", w_ok ? (dw_ok ? 0 : 1) : (at_support ? 1 : 2),
                       where + ": jump of W " + format(w_jump, 4) + ", of dW/dr " + format(dw_jump, 4) +
                           " (in units of h^-D, h^-(D+1))");
        }

        // Negative lobes of W inside the support.
        double minimum = INFINITY, min_q = 0, first_negative = -1;
        for (int i = 0; i <= 4000; ++i) {
            double q = R * i / 4000.0, w = kernel.w(q, dim, check_k);
            if (w < minimum) {
                minimum = w;
                min_q = q;
            }
            if (w < 0 && first_negative < 0) first_negative = q;
        }
        checks.add(dim, "negative_lobe", 0,
                   first_negative < 0 ? "W >= 0 on [0, R]"
                                      : "W < 0 from q = " + format(first_negative, 4) + ", minimum " +
                                            format(minimum, 4) + " at q = " + format(min_q, 4));
    }
    static const char* verdicts[] = {"ok", "warn", "fail"};
    return {{"kernel", kernel.name()},
            {"file", kernel.definition().source},
            {"verdict", verdicts[checks.worst]},
            {"normalization", normalization},
            {"second_moment", second},
            {"checks", checks.items}};
}

nlohmann::json check_kernel_isolated(const Kernel& kernel, double timeout_seconds)
{
    auto result = run_isolated([&] { return check_kernel(kernel).dump(); }, timeout_seconds);
    if (auto* failure = std::get_if<IsolatedFailure>(&result))
        throw Error(ExitCode::plugin, kernel.definition().source + ": kernel " + kernel.name() + " " +
                                          failure->reason + " during the check");
    return nlohmann::json::parse(std::get<std::string>(result));
}

} // namespace sphkern
