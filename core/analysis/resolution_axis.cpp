#include "analysis/resolution_axis.hpp"

#include "lattices/shells.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

Axis parse_axis(const std::string& text, const std::string& what)
{
    if (text == "k") return Axis::k;
    if (text == "h_over_l") return Axis::eta;
    if (text == "eta")
        fail_input(what +
                   " \"eta\" is the old name of sphkern's own h / V^(1/D); expected h_over_l (SWIFT's eta is a code's "
                   "setting: --code swift --eta)");
    if (text == "nh") return Axis::nh;
    fail_unknown(what + " \"" + text + "\" is unknown, expected k, h_over_l or nh");
}

const char* axis_name(Axis axis) { return axis == Axis::k ? "k" : axis == Axis::eta ? "h_over_l" : "nh"; }

double eta_of_k(double k, double a_p, int dimension) { return k / std::pow(a_p, 1.0 / dimension); }
double k_of_eta(double eta, double a_p, int dimension) { return eta * std::pow(a_p, 1.0 / dimension); }

std::pair<double, double> k_window(Axis axis, double lo, double hi, const Kernel& kernel, const Lattice& lattice,
                                   int site, double a_p, const std::string& what)
{
    const int dim = lattice.dimension;
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi && lo > 0))
        fail_input(fmt::format("{}: the window [{}, {}] on the {} axis is not allowed, expected 0 < min < max", what,
                               lo, hi, axis_name(axis)));
    std::pair<double, double> window{lo, hi};
    if (axis == Axis::eta) window = {k_of_eta(lo, a_p, dim), k_of_eta(hi, a_p, dim)};
    if (axis == Axis::nh) {
        // Grow the shells until more than hi neighbours are known (at most the point limit).
        const double R = kernel.support();
        for (double radius = 4;; radius *= 1.5) {
            auto shells = lattice_shells(lattice, site, radius);
            int total = 0;
            double from = 0;
            for (const auto& s : shells) {
                total += s.count;
                if (from == 0 && total >= lo) from = s.radius / R;
                if (total > hi) {
                    if (from == 0 || s.radius / R <= from)
                        fail_input(fmt::format("{}: no k has between {} and {} neighbours inside the support on {}",
                                               what, lo, hi, lattice.name));
                    // Up to, not including, the shell that brings more than hi neighbours.
                    window = {from, std::nextafter(s.radius / (R * (1 + support_edge)), 0.0)};
                    break;
                }
            }
            if (total > hi) break;
        }
    }
    if (!(window.first > 0 && window.second <= 100))
        fail_input(
            fmt::format("{}: the window [{}, {}] on the {} axis is k in [{:.6g}, {:.6g}], expected k in (0, 100]", what,
                        lo, hi, axis_name(axis), window.first, window.second));
    return window;
}

} // namespace sphkern
