#include "analysis/surface_profile.hpp"

#include "lattices/lattice_points.hpp"
#include "kernels/kernel_validity.hpp"
#include "support/error.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sphkern {

GradientForm parse_gradient_form(const std::string& text)
{
    if (text == "sum") return GradientForm::sum;
    if (text == "difference") return GradientForm::difference;
    if (text == "monaghan") return GradientForm::monaghan;
    fail_input("gradient form \"" + text + "\" is unknown, expected sum, difference or monaghan");
}

const char* gradient_form_name(GradientForm form)
{
    return form == GradientForm::sum ? "sum" : form == GradientForm::difference ? "difference" : "monaghan";
}

double layer_spacing(const Lattice& lattice, int site, const Eigen::Vector3d& gravity)
{
    // The projections of nearby lattice points on gravity must be integer multiples
    // of the smallest positive one.
    const double tolerance = 1e-9;
    std::vector<double> projections;
    for_each_lattice_point(lattice.basis, lattice.dimension, lattice.motif, site, 6.0,
                           [&](const Eigen::Vector3d& x) { projections.push_back(std::abs(gravity.dot(x))); });
    double spacing = INFINITY;
    for (double p : projections)
        if (p > tolerance) spacing = std::min(spacing, p);
    bool planar = spacing >= 1e-3 && std::isfinite(spacing);
    for (double p : projections)
        planar = planar && std::abs(p / spacing - std::round(p / spacing)) * spacing <= tolerance;
    if (!planar) {
        std::ostringstream s;
        s << "gravity (";
        for (int i = 0; i < lattice.dimension; ++i) s << (i ? ", " : "") << gravity[i];
        s << ") is not normal to a family of equally spaced planes of lattice " << lattice.name
          << ": a free surface needs a lattice plane (e.g. the lattice's default gravity)";
        fail_input(s.str());
    }
    return spacing;
}

namespace {

struct Neighbour {
    double r;
    double height; // gravity . (x_j - x_i): how much deeper j is than i
    int layer_offset;
};

} // namespace

SurfaceProfile surface_profile(const Kernel& kernel, const Lattice& lattice, int site, double a_p,
                               const Eigen::Vector3d& gravity, double k, int min_layers, GradientForm form)
{
    kernel.require_dimension(lattice.dimension, lattice.name);
    if (!std::isfinite(k) || k <= 0 || k > 100) fail_input("k must be in (0, 100]");
    if (min_layers < 1 || min_layers > 10000) fail_input("the number of layers must be in [1, 10000]");
    const Eigen::Vector3d e = gravity.stableNormalized();
    const int dim = lattice.dimension;
    require_usable_kernel(kernel, dim, k);
    const double reach = kernel.support() * k;
    const double spacing = layer_spacing(lattice, site, e);

    SurfaceProfile profile;
    profile.spacing = spacing;
    std::vector<Neighbour> neighbours;
    for_each_lattice_point(lattice.basis, dim, lattice.motif, site, reach, [&](const Eigen::Vector3d& x) {
        double h = e.dot(x);
        neighbours.push_back({x.norm(), h, static_cast<int>(std::lround(h / spacing))});
    });
    const double kd = std::pow(k, dim), kd1 = kd * k;
    const double self = kernel.w(0, dim, k);
    // Layer n sees the neighbours at most n layers above it; the bulk sees all.
    const int complete = static_cast<int>(std::floor(reach / spacing + 1e-9)) + 1;
    const int reported = std::max(min_layers, form == GradientForm::monaghan ? 2 * complete + 1 : complete + 1);
    const int computed = reported + complete + 1;

    std::vector<double> density(static_cast<std::size_t>(computed));
    std::vector<int> counts(static_cast<std::size_t>(computed));
    for (int n = 0; n < computed; ++n) {
        double sum = self;
        for (const auto& j : neighbours)
            if (j.layer_offset >= -n) {
                sum += kernel.w(j.r / k, dim, k);
                counts[static_cast<std::size_t>(n)] += 1;
            }
        density[static_cast<std::size_t>(n)] = a_p * sum / kd - 1;
    }
    auto layer_density = [&](int n) { return density[static_cast<std::size_t>(std::min(n, computed - 1))]; };

    auto gradient = [&](int n, bool bulk) {
        const double depth_i = bulk ? 0.0 : n * spacing; // in the bulk the P_i terms cancel exactly
        const double rho_i = 1 + (bulk ? layer_density(computed - 1) : layer_density(n));
        double sum = 0;
        for (const auto& j : neighbours) {
            if (!bulk && j.layer_offset < -n) continue;
            double depth_j = depth_i + j.height;
            double weight;
            switch (form) {
            case GradientForm::sum: weight = depth_i + depth_j; break;
            case GradientForm::difference: weight = depth_j - depth_i; break;
            default: {
                double rho_j = 1 + (bulk ? layer_density(computed - 1) : layer_density(n + j.layer_offset));
                weight = rho_i * (depth_i / (rho_i * rho_i) + depth_j / (rho_j * rho_j));
            }
            }
            // (x_i - x_j) . e / r = -height / r
            sum += weight * kernel.dw(j.r / k, dim, k) * (-j.height / j.r);
        }
        return a_p * sum / kd1 - 1;
    };

    for (int n = 0; n < reported; ++n)
        profile.layers.push_back({n, n * spacing, layer_density(n), gradient(n, false), counts[static_cast<std::size_t>(n)]});
    for (const auto& l : profile.layers)
        if (!std::isfinite(l.eps_rho) || !std::isfinite(l.eps_gradp)) {
            for (const auto& j : neighbours) {
                if (!std::isfinite(kernel.w(j.r / k, dim, k))) fail_non_finite_kernel(kernel, "W", j.r / k, dim, k);
                if (!std::isfinite(kernel.dw(j.r / k, dim, k))) fail_non_finite_kernel(kernel, "dW/dr", j.r / k, dim, k);
            }
            fail_input("k = " + std::to_string(k) + " gives non-finite surface errors (expected k of order 1)");
        }
    profile.bulk = {-1, INFINITY, layer_density(computed - 1), gradient(computed - 1, true),
                    static_cast<int>(neighbours.size())};
    return profile;
}

} // namespace sphkern
