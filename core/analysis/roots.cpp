#include "analysis/roots.hpp"

#include "support/process/interruption.hpp"

#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sphkern {

namespace {

// A value this large at a converged bracket means the bracket closed on a pole.
constexpr double singular_value = 1e-6;

void scan_piece(const HydrostaticErrors& errors, double a, double b, std::size_t active, int samples,
                ErrorFunction name, RootScan& out)
{
    auto f = [&](double k) { return value_of(errors.at_piece(k, active), name); };
    double k0 = a, f0 = f(a);
    for (int i = 1; i <= samples; ++i) {
        throw_if_interrupted();
        double k1 = i == samples ? b : a + (b - a) * i / samples;
        double f1 = f(k1);
        if (f0 == 0.0 && k0 == a) {
            out.roots.push_back({name, k0, errors.at_piece(k0, active), errors.kernel().support() * k0});
        } else if (f1 == 0.0) {
            out.roots.push_back({name, k1, errors.at_piece(k1, active), errors.kernel().support() * k1});
        } else if (f0 != 0.0 && std::signbit(f0) != std::signbit(f1) && std::isfinite(f0) && std::isfinite(f1)) {
            std::uintmax_t iterations = 200;
            auto bracket = boost::math::tools::toms748_solve(
                f, k0, k1, f0, f1, [](double lo, double hi) { return hi - lo <= root_tolerance; }, iterations);
            double k = 0.5 * (bracket.first + bracket.second);
            ErrorValues at = errors.at_piece(k, active);
            if (std::abs(value_of(at, name)) <= singular_value)
                out.roots.push_back({name, k, at, errors.kernel().support() * k});
            else out.jumps.push_back({name, JumpKind::singularity, k, f(bracket.first), f(bracket.second)});
        }
        k0 = k1;
        f0 = f1;
    }
}

} // namespace

const char* function_name(ErrorFunction f) { return f == ErrorFunction::rho ? "rho" : "gradp"; }

double value_of(const ErrorValues& v, ErrorFunction f) { return f == ErrorFunction::rho ? v.eps_rho : v.eps_gradp; }

const char* jump_kind_name(JumpKind kind) { return kind == JumpKind::support ? "support" : "singularity"; }

RootScan find_roots(const HydrostaticErrors& errors, double k_min, double k_max, int samples)
{
    RootScan scan;
    std::vector<double> edges = {k_min};
    for (double k : errors.breakpoints(k_min, k_max)) edges.push_back(k);
    edges.push_back(k_max);
    for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
        double a = edges[p], b = edges[p + 1];
        // The shells summed in the open piece: those with R k < r are left out.
        std::size_t active = errors.active_terms(0.5 * (a + b));
        int n = std::max(8, static_cast<int>(std::ceil(samples * (b - a) / (k_max - k_min))));
        for (auto f : {ErrorFunction::rho, ErrorFunction::gradp}) scan_piece(errors, a, b, active, n, f, scan);
        if (p + 1 < edges.size() - 1) {
            std::size_t next = errors.active_terms(0.5 * (b + edges[p + 2]));
            ErrorValues left = errors.at_piece(b, active), right = errors.at_piece(b, next);
            for (auto f : {ErrorFunction::rho, ErrorFunction::gradp}) {
                double l = value_of(left, f), r = value_of(right, f);
                if (l != 0.0 && r != 0.0 && std::signbit(l) != std::signbit(r))
                    scan.jumps.push_back({f, JumpKind::support, b, l, r});
            }
        }
    }
    // A root on a piece edge is found from both sides.
    auto by_function_then_k = [](const Root& x, const Root& y) {
        return x.function != y.function ? x.function < y.function : x.k < y.k;
    };
    std::sort(scan.roots.begin(), scan.roots.end(), by_function_then_k);
    scan.roots.erase(std::unique(scan.roots.begin(), scan.roots.end(),
                                 [](const Root& x, const Root& y) {
                                     return x.function == y.function && std::abs(x.k - y.k) <= 2 * root_tolerance;
                                 }),
                     scan.roots.end());
    std::sort(scan.jumps.begin(), scan.jumps.end(), [](const Jump& x, const Jump& y) { return x.k < y.k; });
    return scan;
}

} // namespace sphkern
