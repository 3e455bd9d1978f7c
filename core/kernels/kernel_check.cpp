#include "kernels/kernel_check.hpp"

#include "kernels/check_status.hpp"
#include "kernels/kernel_integrals.hpp"

#include "kernels/fourier_transform.hpp"
#include "kernels/kernel_spectrum.hpp"
#include "kernels/second_derivative.hpp"
#include "support/error.hpp"
#include "support/process/isolated_call.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sphkern {

namespace {

// The k at which k-dependent formulas (a separate derivative) are checked.
constexpr double check_k = 1.0;

std::string format(double v, int digits = 10)
{
    std::ostringstream s;
    s.precision(digits);
    s << v;
    return s.str();
}

struct CheckItem {
    int dimension = 0;
    std::string name;
    CheckStatus status = CheckStatus::ok;
    std::string detail;
    std::string hint; // empty when ok
};

struct Checks {
    std::vector<CheckItem> items;
    CheckStatus worst = CheckStatus::ok;
    void add(int dim, const std::string& name, CheckStatus status, const std::string& detail,
             const std::string& hint = {})
    {
        if (status != CheckStatus::ok && hint.empty())
            throw std::logic_error("check " + name + " warns or fails without a hint");
        items.push_back({dim, name, status, detail, status == CheckStatus::ok ? std::string() : hint});
        worst = std::max(worst, status);
    }
    nlohmann::json to_json() const
    {
        nlohmann::json json = nlohmann::json::array();
        for (const auto& c : items) {
            nlohmann::json item = {{"dimension", c.dimension},
                                   {"check", c.name},
                                   {"status", check_status_name(c.status)},
                                   {"detail", c.detail}};
            if (!c.hint.empty()) item["hint"] = c.hint;
            json.push_back(std::move(item));
        }
        return json;
    }
};

// The expression file whose keys ("w", "dw", "support") a hint names, or empty: a plugin's
// or a blend's hints name the plugin's functions and descriptor.
std::string expression_file(const Kernel& kernel)
{
    const auto& d = kernel.definition();
    return d.origin == KernelOrigin::expression ? d.source : std::string();
}

// ok when the condition holds, else `otherwise`.
CheckStatus ok_or(bool condition, CheckStatus otherwise) { return condition ? CheckStatus::ok : otherwise; }

// Derivative against a central difference of W, away from breakpoints. Returns the
// largest |dW/dr| on the grid, the scale of the continuity check.
double check_derivative(const Kernel& kernel, int dim, const std::vector<double>& edges, Checks& checks)
{
    const double R = kernel.support();
    double mismatch = 0, scale = 0, worst_q = 0;
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
    const auto& definition = kernel.definition();
    const std::string file = expression_file(kernel);
    if (!definition.derivative_note.empty()) checks.add(dim, "derivative", CheckStatus::ok, definition.derivative_note);
    else if (definition.separate_derivative)
        checks.add(dim, "derivative", CheckStatus::ok,
                   "declared a separate derivative: differs from dW/dr by up to " + format(relative, 3) +
                       " (relative, at q = " + format(worst_q, 4) + ", k = 1); reported, not checked");
    else
        checks.add(dim, "derivative", ok_or(relative <= 1e-6, CheckStatus::fail),
                   "largest relative difference from a numerical dW/dr: " + format(relative, 3) +
                       " at q = " + format(worst_q, 4),
                   file.empty()
                       ? "compare dw with the derivative of w near q = " + format(worst_q, 4) +
                             "; a k-dependent derivative must set SPHKERN_KERNEL_SEPARATE_DERIVATIVE"
                       : "\"dw\" in " + file + " is not the derivative of \"w\" with respect to q near q = " +
                             format(worst_q, 4) + ": correct \"dw\", or leave it out and sphkern differentiates \"w\"");
    return scale;
}

// A provided W'' against a sixth-order difference of dW/dr; without one, say how it is made.
void check_second_derivative(const Kernel& kernel, int dim, const std::vector<double>& edges, Checks& checks)
{
    if (!kernel.provides_second_derivative()) {
        checks.add(
            dim, "second_derivative", CheckStatus::ok,
            "not provided: computed from dW/dr by sixth-order finite differences that never straddle a breakpoint");
        return;
    }
    const double R = kernel.support();
    double mismatch = 0, scale = 0, worst_q = 0;
    for (int i = 1; i < 400; ++i) {
        const double q = R * i / 400.0;
        bool near_edge = false;
        for (double e : edges) near_edge |= std::abs(q - e) < 0.02;
        if (near_edge) continue;
        const double numeric = numerical_second_derivative(kernel, q, dim, check_k),
                     given = kernel.d2w(q, dim, check_k);
        scale = std::max(scale, std::abs(given));
        if (std::abs(given - numeric) > mismatch) mismatch = std::abs(given - numeric), worst_q = q;
    }
    const double relative = mismatch / std::max(scale, 1e-300);
    checks.add(dim, "second_derivative", ok_or(relative <= 1e-6, CheckStatus::fail),
               "provided; largest relative difference from a numerical derivative of dW/dr: " + format(relative, 3) +
                   " at q = " + format(worst_q, 4),
               "compare d2w with the derivative of dw near q = " + format(worst_q, 4));
}

// Continuity of W and dW/dr at each breakpoint and at R (where the host truncates);
// `dw_scale` is the largest |dW/dr| inside the support.
void check_continuity(const Kernel& kernel, int dim, const std::vector<double>& edges, double dw_scale, Checks& checks)
{
    const double w0 = std::abs(kernel.w(0, dim, check_k));
    dw_scale = std::max(dw_scale, 1e-300);
    const std::string file = expression_file(kernel);
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
        const CheckStatus status =
            w_ok ? ok_or(dw_ok, CheckStatus::warn) : (at_support ? CheckStatus::warn : CheckStatus::fail);
        std::string hint;
        if (at_support)
            hint = (file.empty() ? "W or dW/dr does not reach zero at R"
                                 : "\"w\" or \"dw\" in " + file + " is not zero at \"support\" = " + format(b)) +
                   ": the errors jump where a shell crosses the support; a kernel that ends smoothly at R avoids it";
        else
            hint = (file.empty() ? "the pieces" : "the pieces of \"w\" or \"dw\" in " + file) +
                   " do not meet at q = " + format(b) + ": check each piece's formula and constant there";
        checks.add(dim, "continuity", status,
                   where + ": jump of W " + format(w_jump, 4) + ", of dW/dr " + format(dw_jump, 4) +
                       " (in units of h^-D, h^-(D+1))",
                   hint);
    }
}

// Where W or dW/dr breaks off a smooth curve away from the declared breakpoints.
// Second differences on a grid are O(delta^2) and slowly varying on a smooth piece; at a
// kink one of the two straddling points has O(delta), at a jump O(1). A difference far
// above those three points away on both sides marks a break.
void check_breakpoints(const Kernel& kernel, int dim, Checks& checks)
{
    const double R = kernel.support();
    const auto edges = piece_edges(kernel);
    const int n = 4000;
    const double delta = R / n;
    auto near_edge = [&](double q, double reach) {
        for (double e : edges)
            if (std::abs(q - e) <= reach) return true;
        return false;
    };
    std::string found;
    for (bool derivative : {false, true}) {
        std::vector<double> f(n + 1), d(n + 1, 0.0);
        double scale = 0;
        for (int i = 0; i <= n; ++i) {
            f[i] = derivative ? kernel.dw(delta * i, dim, check_k) : kernel.w(delta * i, dim, check_k);
            scale = std::max(scale, std::abs(f[i]));
        }
        for (int i = 1; i < n; ++i) d[i] = std::abs(f[i + 1] - 2 * f[i] + f[i - 1]);
        for (int i = 4; i + 4 <= n && found.empty(); ++i) {
            const double q = delta * i;
            if (near_edge(q, 5 * delta) || d[i] <= 1e-9 * scale) continue;
            if (d[i] > 20 * std::max(d[i - 3], d[i + 3]))
                found = std::string("W") + (derivative ? "'" : "") + " is not smooth near q = " + format(q, 4) +
                        (derivative ? " (a kink or jump in dW/dr)" : " (a jump or kink in W)");
        }
        if (!found.empty()) break;
    }
    const std::string file = expression_file(kernel);
    checks.add(dim, "breakpoints", ok_or(found.empty(), CheckStatus::warn),
               found.empty() ? "W and dW/dr smooth between the declared breakpoints"
                             : found + ", which is not a declared breakpoint",
               (file.empty() ? "declare the breakpoint" : "add that q to \"breakpoints\" in " + file) +
                   " (or fix the formula): quadratures and derivatives are split at breakpoints only");
}

// A support larger than the kernel: W = 0 on the last part of [0, R]. Exactly zero, not
// small: W ~ (R - q)^8 is tiny but still the kernel near R.
void check_support(const Kernel& kernel, int dim, Checks& checks)
{
    const double R = kernel.support();
    const int n = 4000;
    const double delta = R / n;
    double last = 0;
    for (int i = n - 1; i >= 0; --i)
        if (kernel.w(R * i / n, dim, check_k) != 0.0) {
            last = R * i / n;
            break;
        }
    const bool over = last < R * 0.99;
    const std::string file = expression_file(kernel);
    checks.add(dim, "support", over ? CheckStatus::warn : CheckStatus::ok,
               over ? "W is zero from q = " + format(last + delta, 4) + " to the declared support R = " + format(R)
                    : "W is non-zero up to the declared support R = " + format(R),
               (file.empty() ? "declare the support where W ends"
                             : "set \"support\" in " + file + " where \"w\" ends") +
                   ": R sets the neighbour count N_H, H/d and the k windows");
}

// The integral of the formula past R, out to 4 R: what truncation at R cuts off. Not
// finite (a formula that grows past R) means nothing a truncation explains.
double tail_integral(const Kernel& kernel, int dim)
{
    const double R = kernel.support();
    double total = 0;
    try {
        for (int piece = 0; piece < 3; ++piece)
            total += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
                [&](double q) { return kernel.w(q, dim, check_k) * std::pow(q, dim - 1); }, R * (1 + piece),
                R * (2 + piece), 15, 1e-15);
    } catch (const std::exception&) {
        return NAN;
    }
    return sphere_area(dim) * total;
}

// Normalisation of the truncated kernel; returns its integral. |integral - 1| <= 1e-9 is
// ok. A larger deviation that the part of the formula cut off at R accounts for (to 1e-6)
// is a truncation: a warning. Anything else is a wrong normalisation constant and fails
// above 1e-6: eps_rho inherits it one to one.
double check_normalization(const Kernel& kernel, int dim, Checks& checks)
{
    const auto [integral, error] = kernel_integral(kernel, dim, check_k);
    const double deviation = std::abs(integral - 1);
    std::string detail =
        "integral of W = " + format(integral) + " (quadrature error estimate " + format(error, 2) + ")";
    if (kernel.definition().normalised) detail += "; \"normalise\": true, so sphkern divides \"w\" by its integral";
    const std::string file = expression_file(kernel), D = std::to_string(dim) + "D";
    if (deviation <= normalization_ok) {
        checks.add(dim, "normalization", CheckStatus::ok, detail);
        return integral;
    }
    const double whole = integral + tail_integral(kernel, dim);
    if (std::isfinite(whole) && std::abs(whole - 1) <= normalization_truncation) {
        checks.add(dim, "normalization", deviation <= normalization_warn ? CheckStatus::warn : CheckStatus::fail,
                   detail + "; the formula continued past R integrates to " + format(whole),
                   file.empty()
                       ? "normalised over all space, not over the support: cutting the formula at R changes its "
                         "integral by " +
                             format(integral - 1, 3) + "; divide W by " + format(integral) + " in " + D +
                             " or choose a larger R"
                       : "\"w\" in " + file +
                             " is normalised over all space, not over \"support\": cutting the "
                             "formula at R changes its integral by " +
                             format(integral - 1, 3) +
                             "; multiply \"w\" and "
                             "\"dw\" by " +
                             format(1 / integral) + " in " + D +
                             ", choose a larger \"support\", or set \"normalise\": true");
        return integral;
    }
    std::string hint;
    if (file.empty()) {
        hint = "the normalisation constant is off by a factor " + format(integral) + " in " + D +
               " (eps_rho inherits it one to one): divide the " + D + " constant by " + format(integral);
    } else {
        // The right constant as the W(0) it gives: the constant itself where the rest of the
        // formula is 1 at q = 0, as usual.
        const double w0 = kernel.w(0, dim, check_k);
        hint = "the constant of \"w\" in " + file + " is off by a factor " + format(integral) + " in " + D +
               " (eps_rho inherits it one to one): multiply \"w\" and \"dw\" by " + format(1 / integral) + " in " + D;
        if (w0 != 0)
            hint += ", so that W(0) = " + format(w0 / integral) +
                    " (the right constant where the rest of \"w\" is 1 at q = 0)";
        if (kernel.definition().dimensions.size() > 1)
            hint += "; one formula has one constant for all its \"dimensions\": give " + D + " a file of its own";
        hint += ", or set \"normalise\": true";
    }
    checks.add(dim, "normalization", deviation <= normalization_truncation ? CheckStatus::warn : CheckStatus::fail,
               detail, hint);
    return integral;
}

// Finiteness of W and dW/dr on a grid past R and at several k.
void check_finiteness(const Kernel& kernel, int dim, Checks& checks)
{
    const double R = kernel.support();
    const std::string file = expression_file(kernel);
    int bad = 0;
    double bad_q = 0;
    for (double k : {0.75, 1.0, 1.25})
        for (int i = 0; i <= 2000; ++i) {
            double q = 1.5 * R * i / 2000;
            if (!std::isfinite(kernel.w(q, dim, k)) || !std::isfinite(kernel.dw(q, dim, k))) {
                if (!bad++) bad_q = q;
            }
        }
    checks.add(dim, "finiteness", bad ? CheckStatus::fail : CheckStatus::ok,
               bad ? std::to_string(bad) + " non-finite values, first at q = " + format(bad_q)
                   : "W and dW/dr finite on [0, 1.5 R] at k = 0.75, 1, 1.25",
               (file.empty() ? std::string() : "\"w\" or \"dw\" in " + file + ": ") +
                   "a division by zero or a power of a negative number near q = " + format(bad_q) +
                   "? every q >= 0 must give a finite value");
}

// The moment of the gradient: integral of x . grad W over D-space = -D for a normalised
// kernel that vanishes at R (by parts); it sees a wrong dW/dr and a jump at R, which the
// normalisation alone cannot. `integral` is the integral of W.
void check_gradient_moment(const Kernel& kernel, int dim, double integral, Checks& checks)
{
    const double R = kernel.support();
    const double moment = radial_integral(kernel, dim, [&](double q) { return kernel.dw(q, dim, check_k) * q; }).first;
    // A jump of W at R leaves out the surface term of the integration by parts.
    const double surface = sphere_area(dim) * std::pow(R, dim) * kernel.w(R * (1 - 1e-12), dim, check_k);
    const double expected = -dim * integral + surface;
    const bool consistent = std::abs(moment - expected) <= 1e-6 * dim;
    const bool jump_at_support = std::abs(surface) > 1e-6 * dim;
    std::string detail =
        "integral of x . grad W = " + format(moment) + "; -D times the integral of W = " + format(-dim * integral);
    if (jump_at_support) detail += ", plus the surface term the jump of W at R leaves out, " + format(surface, 4);
    if (kernel.definition().separate_derivative) {
        checks.add(dim, "gradient_moment", CheckStatus::ok,
                   detail +
                       "; a separate derivative: reported, not checked (it is the continuum gradient error times -D)");
        return;
    }
    const std::string file = expression_file(kernel);
    std::string hint;
    if (consistent)
        hint = (file.empty() ? "W does not vanish at R"
                             : "\"w\" in " + file + " does not vanish at \"support\" = " + format(R)) +
               ": the truncated kernel's gradient misses a surface term";
    else
        hint = (file.empty() ? "dW/dr is not the derivative of W"
                             : "\"dw\" in " + file + " is not the derivative of \"w\"") +
               " (a wrong factor or sign?)";
    checks.add(dim, "gradient_moment", consistent ? ok_or(!jump_at_support, CheckStatus::warn) : CheckStatus::fail,
               detail, hint);
}

// The second moment, the kernel's width in units of h^2 (reported); returns it.
double check_second_moment(const Kernel& kernel, int dim, Checks& checks)
{
    const double width = kernel_integral(kernel, dim, check_k, 2).first;
    checks.add(dim, "second_moment", CheckStatus::ok, "integral of q^2 W = " + format(width) + " (in units of h^2)");
    return width;
}

// A provided Fourier transform against the radial quadrature of W.
void check_provided_transform(const Kernel& kernel, int dim, Checks& checks)
{
    double worst = 0, at = 0;
    for (int i = 0; i <= 200; ++i) {
        const double kh = 0.25 * i;
        const double d =
            std::abs(kernel.fourier(kh, dim, check_k) - fourier_transform_by_quadrature(kernel, kh, dim, check_k));
        if (d > worst) worst = d, at = kh;
    }
    checks.add(dim, "fourier_provided", ok_or(worst <= 1e-8, CheckStatus::fail),
               "provided transform; largest difference from the quadrature of W: " + format(worst, 3) +
                   " at kh = " + format(at, 4),
               "the transform must be that of the normalised W, as a function of kappa h");
}

// The Fourier transform's minimum and first zero (a negative W^ pairs particles), and a
// provided transform against the quadrature of W. Returns the "fourier" entry.
nlohmann::json check_fourier(const Kernel& kernel, int dim, Checks& checks)
{
    auto spectrum = spectrum_summary(kernel, dim, check_k);
    nlohmann::json entry = {{"min", spectrum.minimum},
                            {"at", spectrum.at},
                            {"at_zero", kernel.fourier(0, dim, check_k)},
                            {"source", spectrum.provided ? "plugin" : "quadrature"}};
    entry["first_zero"] = spectrum.first_zero ? nlohmann::json(*spectrum.first_zero) : nlohmann::json();
    checks.add(dim, "fourier", spectrum.minimum < -1e-9 ? CheckStatus::warn : CheckStatus::ok,
               "min of the Fourier transform over kh in [0, 50]: " + format(spectrum.minimum, 4) +
                   " at kh = " + format(spectrum.at, 5) +
                   (spectrum.first_zero ? ", first zero at kh = " + format(*spectrum.first_zero, 6) : ", no zero"),
               "negative W^: with many neighbours SPH pairs particles (Dehnen & Aly 2012); see sphkern stability");
    if (spectrum.provided) check_provided_transform(kernel, dim, checks);
    return entry;
}

// Negative lobes of W inside the support (reported).
void check_negative_lobe(const Kernel& kernel, int dim, Checks& checks)
{
    const double R = kernel.support();
    double minimum = INFINITY, min_q = 0, first_negative = -1;
    for (int i = 0; i <= 4000; ++i) {
        double q = R * i / 4000.0, w = kernel.w(q, dim, check_k);
        if (w < minimum) {
            minimum = w;
            min_q = q;
        }
        if (w < 0 && first_negative < 0) first_negative = q;
    }
    checks.add(dim, "negative_lobe", CheckStatus::ok,
               first_negative < 0 ? "W >= 0 on [0, R]"
                                  : "W < 0 from q = " + format(first_negative, 4) + ", minimum " + format(minimum, 4) +
                                        " at q = " + format(min_q, 4));
}

} // namespace

nlohmann::json check_kernel(const Kernel& kernel)
{
    Checks checks;
    nlohmann::json normalization = nlohmann::json::object(), second = nlohmann::json::object();
    nlohmann::json fourier = nlohmann::json::object();
    const auto edges = piece_edges(kernel);
    for (int dim : kernel.definition().dimensions) {
        const std::string D = std::to_string(dim);
        check_finiteness(kernel, dim, checks);
        const double integral = check_normalization(kernel, dim, checks);
        normalization[D] = integral;
        check_gradient_moment(kernel, dim, integral, checks);
        second[D] = check_second_moment(kernel, dim, checks);
        const double dw_scale = check_derivative(kernel, dim, edges, checks);
        check_second_derivative(kernel, dim, edges, checks);
        check_continuity(kernel, dim, edges, dw_scale, checks);
        check_breakpoints(kernel, dim, checks);
        check_support(kernel, dim, checks);
        fourier[D] = check_fourier(kernel, dim, checks);
        check_negative_lobe(kernel, dim, checks);
    }
    return {{"kernel", kernel.name()},
            {"file", kernel.definition().source},
            {"verdict", check_status_name(checks.worst)},
            {"normalization", normalization},
            {"second_moment", second},
            {"fourier", fourier},
            {"second_derivative", kernel.provides_second_derivative() ? "plugin" : "numerical"},
            {"checks", checks.to_json()}};
}

nlohmann::json check_kernel_isolated(const Kernel& kernel, double timeout_seconds)
{
    auto result = run_isolated([&] { return check_kernel(kernel).dump(); }, timeout_seconds);
    if (auto* failure = std::get_if<IsolatedFailure>(&result))
        throw Error(ExitCode::plugin, kernel.definition().source + ": kernel " + kernel.name() + " " + failure->reason +
                                          " during the check");
    return nlohmann::json::parse(std::get<std::string>(result));
}

} // namespace sphkern
