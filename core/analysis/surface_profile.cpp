#include "analysis/surface_profile.hpp"

#include "support/interruption.hpp"

#include "lattices/lattice_points.hpp"
#include "kernels/kernel_validity.hpp"
#include "support/error.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sphkern {

int SurfacePlanes::type_of_site(int site) const
{
    for (std::size_t t = 0; t < types.size(); ++t)
        if (std::find(types[t].sites.begin(), types[t].sites.end(), site) != types[t].sites.end()) return static_cast<int>(t);
    return 0;
}

std::string SurfacePlanes::name(int type) const
{
    std::string s = types[static_cast<std::size_t>(type)].sites.size() > 1 ? "sites " : "site ";
    for (std::size_t i = 0; i < types[static_cast<std::size_t>(type)].sites.size(); ++i) {
        if (i) s += ',';
        s += std::to_string(types[static_cast<std::size_t>(type)].sites[i]);
    }
    return s;
}

SurfacePlanes surface_planes(const Lattice& lattice, const Eigen::Vector3d& gravity)
{
    // The Bravais projections on gravity must be integer multiples of the smallest positive one.
    const double tolerance = 1e-9;
    const std::vector<Eigen::Vector3d> origin_only = {Eigen::Vector3d::Zero()};
    std::vector<double> projections;
    for_each_lattice_point(lattice.basis, lattice.dimension, origin_only, 0, 6.0,
                           [&](const Eigen::Vector3d& x) { projections.push_back(std::abs(gravity.dot(x))); });
    double period = INFINITY;
    for (double p : projections)
        if (p > tolerance) period = std::min(period, p);
    bool planar = period >= 1e-3 && std::isfinite(period);
    for (double p : projections)
        planar = planar && std::abs(p / period - std::round(p / period)) * period <= tolerance;
    if (!planar) {
        std::ostringstream s;
        s << "gravity (";
        for (int i = 0; i < lattice.dimension; ++i) s << (i ? ", " : "") << gravity[i];
        s << ") is not normal to a family of lattice planes of lattice " << lattice.name
          << ": a free surface needs a lattice plane (e.g. the lattice's default gravity)";
        fail_input(s.str());
    }
    SurfacePlanes planes;
    planes.period = period;
    for (int site = 0; site < lattice.sites(); ++site) {
        double offset = std::fmod(gravity.dot(lattice.basis * lattice.motif[static_cast<std::size_t>(site)]), period);
        if (offset < 0) offset += period;
        if (period - offset <= tolerance) offset = 0;
        auto same = std::find_if(planes.types.begin(), planes.types.end(),
                                 [&](const PlaneType& t) { return std::abs(t.offset - offset) <= tolerance; });
        if (same != planes.types.end()) same->sites.push_back(site);
        else planes.types.push_back({offset, {site}});
    }
    std::sort(planes.types.begin(), planes.types.end(), [](const PlaneType& a, const PlaneType& b) { return a.offset < b.offset; });
    return planes;
}

namespace {

struct Neighbour {
    double r;
    double height; // gravity . (x_j - x_i): how much deeper j is than i
    int site;      // the motif site of j
};

struct Plane {
    double depth;
    int type;
};

} // namespace

SurfaceProfile surface_profile(const Kernel& kernel, const Lattice& lattice, int site, double a_p,
                               const Eigen::Vector3d& gravity, double k, int min_layers, GradientForm form,
                               std::optional<int> termination)
{
    kernel.require_dimension(lattice.dimension, lattice.name);
    if (!std::isfinite(k) || k <= 0 || k > 100) fail_input("k must be in (0, 100]");
    if (min_layers < 1 || min_layers > 10000) fail_input("the number of layers must be in [1, 10000]");
    if (site < 0 || site >= lattice.sites())
        fail_input("site " + std::to_string(site) + " does not exist; lattice " + lattice.name + " has sites 0 to " +
                   std::to_string(lattice.sites() - 1));
    const Eigen::Vector3d e = gravity.stableNormalized();
    const int dim = lattice.dimension, sites = lattice.sites();
    require_usable_kernel(kernel, dim, k);
    const double reach = kernel.support() * k;

    SurfaceProfile profile;
    profile.planes = surface_planes(lattice, e);
    profile.spacing = profile.planes.period;
    const int types = static_cast<int>(profile.planes.types.size());
    if (termination && (*termination < 0 || *termination >= types))
        fail_input("termination " + std::to_string(*termination) + " does not exist; lattice " + lattice.name +
                   " has " + std::to_string(types) + " plane type(s) normal to this gravity, 0 to " +
                   std::to_string(types - 1));
    profile.termination = termination ? *termination : profile.planes.type_of_site(site);
    const double period = profile.planes.period, top_offset = profile.planes.types[profile.termination].offset;

    // The occupied planes below the top, in depth order, deep enough for the reported planes
    // and their neighbours' densities.
    // A plane deeper than the reach has every neighbour; with Monaghan's form its neighbours
    // need theirs too (a period more than the reach again, as a whole number of periods).
    const double reported_depth =
        form == GradientForm::monaghan ? reach + (std::floor(reach / period + 1e-9) + 1) * period : reach;
    const double deepest = reported_depth + reach + (min_layers + 1) * period;
    std::vector<Plane> planes;
    for (int t = 0; t < types; ++t) {
        double first = std::fmod(profile.planes.types[t].offset - top_offset + period, period);
        if (period - first <= 1e-9) first = 0;
        for (int n = 0; first + n * period <= deepest; ++n) planes.push_back({first + n * period, t});
    }
    std::sort(planes.begin(), planes.end(), [](const Plane& a, const Plane& b) { return a.depth < b.depth; });
    auto plane_at = [&](double depth) -> int { // index of the plane at this depth, or -1 past the list
        auto it = std::lower_bound(planes.begin(), planes.end(), depth - 1e-9,
                                   [](const Plane& p, double d) { return p.depth < d; });
        return it == planes.end() ? -1 : static_cast<int>(it - planes.begin());
    };

    std::vector<std::vector<Neighbour>> neighbours(static_cast<std::size_t>(sites));
    for (int s = 0; s < sites; ++s)
        for_each_lattice_point_of_site(lattice.basis, dim, lattice.motif, s, reach * (1 + support_edge),
                                       [&](const Eigen::Vector3d& x, int t) {
                                           neighbours[static_cast<std::size_t>(s)].push_back({x.norm(), e.dot(x), t});
                                       });
    const double kd = std::pow(k, dim), kd1 = kd * k;
    const double self = kernel.w(0, dim, k);

    // Densities of every (plane, site on it), and of each site in the bulk.
    auto density_of = [&](int s, double depth, bool bulk, int* count) {
        double sum = self;
        for (const auto& j : neighbours[static_cast<std::size_t>(s)])
            if (bulk || depth + j.height >= -1e-9) {
                sum += kernel.w(j.r / k, dim, k);
                if (count) *count += 1;
            }
        return a_p * sum / kd - 1;
    };
    std::vector<double> bulk_density(static_cast<std::size_t>(sites));
    for (int s = 0; s < sites; ++s) bulk_density[static_cast<std::size_t>(s)] = density_of(s, 0, true, nullptr);
    std::vector<std::vector<double>> density(planes.size(), std::vector<double>(static_cast<std::size_t>(sites)));
    for (std::size_t p = 0; p < planes.size(); ++p) {
        throw_if_interrupted(); // thousands of planes at a large k: a signal stops between them
        for (int s : profile.planes.types[static_cast<std::size_t>(planes[p].type)].sites)
            density[p][static_cast<std::size_t>(s)] = density_of(s, planes[p].depth, false, nullptr);
    }
    auto density_at = [&](int s, double depth) {
        int p = plane_at(depth);
        return p < 0 ? bulk_density[static_cast<std::size_t>(s)] : density[static_cast<std::size_t>(p)][static_cast<std::size_t>(s)];
    };

    auto gradient = [&](int s, double depth_i, bool bulk) {
        if (bulk) depth_i = 0.0; // in the bulk the P_i terms cancel on a centre of inversion (see first_moments)
        const double rho_i = 1 + (bulk ? bulk_density[static_cast<std::size_t>(s)] : density_at(s, depth_i));
        double sum = 0;
        for (const auto& j : neighbours[static_cast<std::size_t>(s)]) {
            double depth_j = depth_i + j.height;
            if (!bulk && depth_j < -1e-9) continue;
            const double rho_j = form != GradientForm::monaghan ? 1.0 // read by the Monaghan form only
                                 : 1 + (bulk ? bulk_density[static_cast<std::size_t>(j.site)] : density_at(j.site, depth_j));
            const double weight = gradient_form_weight(form, depth_i, depth_j, rho_i, rho_j);
            // (x_i - x_j) . e / r = -height / r
            sum += weight * kernel.dw(j.r / k, dim, k) * (-j.height / j.r);
        }
        return a_p * sum / kd1 - 1;
    };

    auto site_values = [&](int s, double depth, bool bulk) {
        SiteLayerErrors v{s, 0, 0, 0};
        v.eps_rho = density_of(s, depth, bulk, &v.neighbours);
        v.eps_gradp = gradient(s, depth, bulk);
        return v;
    };
    // Report until every plane type has been seen below the reach (then each equals its bulk).
    std::vector<bool> complete(static_cast<std::size_t>(types), false);
    for (std::size_t p = 0; p < planes.size(); ++p) {
        if (static_cast<int>(p) >= min_layers && std::all_of(complete.begin(), complete.end(), [](bool c) { return c; }))
            break;
        if (planes[p].depth > reported_depth + 1e-9) complete[static_cast<std::size_t>(planes[p].type)] = true;
        throw_if_interrupted();
        LayerErrors layer;
        layer.n = static_cast<int>(p);
        layer.depth = planes[p].depth;
        for (int s : profile.planes.types[static_cast<std::size_t>(planes[p].type)].sites)
            layer.sites.push_back(site_values(s, planes[p].depth, false));
        layer.eps_rho = layer.sites[0].eps_rho;
        layer.eps_gradp = layer.sites[0].eps_gradp;
        layer.neighbours = layer.sites[0].neighbours;
        profile.layers.push_back(layer);
    }
    for (const auto& l : profile.layers)
        for (const auto& v : l.sites)
            if (!std::isfinite(v.eps_rho) || !std::isfinite(v.eps_gradp)) {
                for (const auto& j : neighbours[static_cast<std::size_t>(v.site)]) {
                    if (!std::isfinite(kernel.w(j.r / k, dim, k))) fail_non_finite_kernel(kernel, "W", j.r / k, dim, k);
                    if (!std::isfinite(kernel.dw(j.r / k, dim, k))) fail_non_finite_kernel(kernel, "dW/dr", j.r / k, dim, k);
                }
                fail_input("k = " + std::to_string(k) + " gives non-finite surface errors (expected k of order 1)");
            }
    profile.bulk.n = -1;
    profile.bulk.depth = INFINITY;
    for (int s = 0; s < sites; ++s) {
        profile.bulk.sites.push_back(site_values(s, 0, true));
        profile.first_moments.push_back(HydrostaticErrors(kernel, lattice, s, a_p, e, k).tensor(k).first_moment);
    }
    const auto& top_site = profile.bulk.sites[static_cast<std::size_t>(profile.layers[0].sites[0].site)];
    profile.bulk.eps_rho = top_site.eps_rho;
    profile.bulk.eps_gradp = top_site.eps_gradp;
    profile.bulk.neighbours = top_site.neighbours;
    return profile;
}

} // namespace sphkern
