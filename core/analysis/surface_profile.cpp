#include "analysis/surface_profile.hpp"

#include "support/process/interruption.hpp"

#include "kernels/kernel_validity.hpp"
#include "lattices/lattice_points.hpp"
#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sphkern {

int SurfacePlanes::type_of_site(int site) const
{
    for (std::size_t t = 0; t < types.size(); ++t)
        if (std::find(types[t].sites.begin(), types[t].sites.end(), site) != types[t].sites.end())
            return static_cast<int>(t);
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
    for (double p : projections) planar = planar && std::abs(p / period - std::round(p / period)) * period <= tolerance;
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
    std::sort(planes.types.begin(), planes.types.end(),
              [](const PlaneType& a, const PlaneType& b) { return a.offset < b.offset; });
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

void require_surface_inputs(const Kernel& kernel, const Lattice& lattice, int site, double k, int min_layers)
{
    kernel.require_dimension(lattice.dimension, lattice.name);
    // Guards only: every front end refuses k and the site first, naming them (the surface
    // request for the command line and Python; a study reads k in [1e-3, 100] and uses site 0).
    check_k(k, ValueSource::argument("k"));
    check_site(site, lattice.sites(), lattice.name, {});
    if (min_layers < 1 || min_layers > max_surface_layers)
        fail_input("the number of layers must be in [1, " + std::to_string(max_surface_layers) + "]");
}

// The plane type on top: `termination` if given, else the type holding `site`.
int top_plane_type(const SurfacePlanes& planes, const Lattice& lattice, int site, std::optional<int> termination)
{
    const int types = static_cast<int>(planes.types.size());
    if (termination && (*termination < 0 || *termination >= types))
        fail_input("termination " + std::to_string(*termination) + " does not exist; lattice " + lattice.name +
                   " has " + std::to_string(types) + " plane type(s) normal to this gravity, 0 to " +
                   std::to_string(types - 1));
    return termination ? *termination : planes.type_of_site(site);
}

// The occupied planes from the top one (of type `top`) down to `deepest`, in depth order.
std::vector<Plane> planes_below_top(const SurfacePlanes& types, int top, double deepest)
{
    const double period = types.period, top_offset = types.types[static_cast<std::size_t>(top)].offset;
    std::vector<Plane> planes;
    for (int t = 0; t < static_cast<int>(types.types.size()); ++t) {
        double first = std::fmod(types.types[static_cast<std::size_t>(t)].offset - top_offset + period, period);
        if (period - first <= 1e-9) first = 0;
        for (int n = 0; first + n * period <= deepest; ++n) planes.push_back({first + n * period, t});
    }
    std::sort(planes.begin(), planes.end(), [](const Plane& a, const Plane& b) { return a.depth < b.depth; });
    return planes;
}

// The lattice sums below a free surface: each site's neighbours within the support, the
// densities of every (plane, site on it) and of each site in the bulk, and from them the
// errors of a particle at a depth.
class SurfaceSums {
public:
    SurfaceSums(const Kernel& kernel, const Lattice& lattice, const SurfacePlanes& types, std::vector<Plane> planes,
                double a_p, const Eigen::Vector3d& e, double k, GradientForm form)
        : kernel_(kernel), types_(types), planes_(std::move(planes)), dim_(lattice.dimension), a_p_(a_p), k_(k),
          form_(form), kd_(std::pow(k, lattice.dimension)), self_(kernel.w(0, lattice.dimension, k))
    {
        find_neighbours(lattice, e);
        find_densities(lattice.sites());
    }

    // Planes 0, 1, ... until every plane type has been seen deeper than `reported_depth`
    // (then each equals its bulk), and at least `min_layers`.
    std::vector<LayerErrors> layers(double reported_depth, int min_layers) const;
    // Throws on a non-finite error: the kernel's value that caused it, else k far from 1.
    void require_finite(const std::vector<LayerErrors>& layers) const;
    // Every neighbour present; the summary values of site `top_site`.
    LayerErrors bulk(int top_site) const;

private:
    void find_neighbours(const Lattice& lattice, const Eigen::Vector3d& e);
    void find_densities(int sites);
    double density_of(int s, double depth, bool bulk, int* count) const;
    double density_at(int s, double depth) const;
    double gradient(int s, double depth_i, bool bulk) const;
    SiteLayerErrors site_values(int s, double depth, bool bulk) const;
    const std::vector<Neighbour>& neighbours_of(int s) const { return neighbours_[static_cast<std::size_t>(s)]; }

    const Kernel& kernel_;
    const SurfacePlanes& types_;
    const std::vector<Plane> planes_;
    const int dim_;
    const double a_p_, k_;
    const GradientForm form_;
    const double kd_, self_;
    std::vector<std::vector<Neighbour>> neighbours_;
    std::vector<double> bulk_density_;
    std::vector<std::vector<double>> density_; // by plane, then site
};

void SurfaceSums::find_neighbours(const Lattice& lattice, const Eigen::Vector3d& e)
{
    const double reach = kernel_.support() * k_;
    neighbours_.resize(static_cast<std::size_t>(lattice.sites()));
    for (int s = 0; s < lattice.sites(); ++s)
        for_each_lattice_point_of_site(lattice.basis, dim_, lattice.motif, s, reach * (1 + support_edge),
                                       [&](const Eigen::Vector3d& x, int t) {
                                           neighbours_[static_cast<std::size_t>(s)].push_back({x.norm(), e.dot(x), t});
                                       });
}

void SurfaceSums::find_densities(int sites)
{
    bulk_density_.resize(static_cast<std::size_t>(sites));
    for (int s = 0; s < sites; ++s) bulk_density_[static_cast<std::size_t>(s)] = density_of(s, 0, true, nullptr);
    density_.assign(planes_.size(), std::vector<double>(static_cast<std::size_t>(sites)));
    for (std::size_t p = 0; p < planes_.size(); ++p) {
        throw_if_interrupted(); // thousands of planes at a large k: a signal stops between them
        for (int s : types_.types[static_cast<std::size_t>(planes_[p].type)].sites)
            density_[p][static_cast<std::size_t>(s)] = density_of(s, planes_[p].depth, false, nullptr);
    }
}

// eps_rho of site s at a depth (neighbours above the surface missing unless in the bulk);
// counts the neighbours present into *count when given.
double SurfaceSums::density_of(int s, double depth, bool bulk, int* count) const
{
    double sum = self_;
    for (const auto& j : neighbours_of(s))
        if (bulk || depth + j.height >= -1e-9) {
            sum += kernel_.w(j.r / k_, dim_, k_);
            if (count) *count += 1;
        }
    return a_p_ * sum / kd_ - 1;
}

// The density found for site s on the plane at this depth; the bulk's past the list.
double SurfaceSums::density_at(int s, double depth) const
{
    auto it = std::lower_bound(planes_.begin(), planes_.end(), depth - 1e-9,
                               [](const Plane& p, double d) { return p.depth < d; });
    if (it == planes_.end()) return bulk_density_[static_cast<std::size_t>(s)];
    return density_[static_cast<std::size_t>(it - planes_.begin())][static_cast<std::size_t>(s)];
}

double SurfaceSums::gradient(int s, double depth_i, bool bulk) const
{
    if (bulk) depth_i = 0.0; // in the bulk the P_i terms cancel on a centre of inversion (see first_moments)
    const double rho_i = 1 + (bulk ? bulk_density_[static_cast<std::size_t>(s)] : density_at(s, depth_i));
    double sum = 0;
    for (const auto& j : neighbours_of(s)) {
        double depth_j = depth_i + j.height;
        if (!bulk && depth_j < -1e-9) continue;
        const double rho_j =
            form_ != GradientForm::monaghan
                ? 1.0 // read by the Monaghan form only
                : 1 + (bulk ? bulk_density_[static_cast<std::size_t>(j.site)] : density_at(j.site, depth_j));
        const double weight = gradient_form_weight(form_, depth_i, depth_j, rho_i, rho_j);
        // (x_i - x_j) . e / r = -height / r
        sum += weight * kernel_.dw(j.r / k_, dim_, k_) * (-j.height / j.r);
    }
    return a_p_ * sum / (kd_ * k_) - 1;
}

SiteLayerErrors SurfaceSums::site_values(int s, double depth, bool bulk) const
{
    SiteLayerErrors v{s, 0, 0, 0};
    v.eps_rho = density_of(s, depth, bulk, &v.neighbours);
    v.eps_gradp = gradient(s, depth, bulk);
    return v;
}

std::vector<LayerErrors> SurfaceSums::layers(double reported_depth, int min_layers) const
{
    std::vector<LayerErrors> layers;
    std::vector<bool> complete(types_.types.size(), false);
    for (std::size_t p = 0; p < planes_.size(); ++p) {
        if (static_cast<int>(p) >= min_layers &&
            std::all_of(complete.begin(), complete.end(), [](bool c) { return c; }))
            break;
        if (planes_[p].depth > reported_depth + 1e-9) complete[static_cast<std::size_t>(planes_[p].type)] = true;
        throw_if_interrupted();
        LayerErrors layer;
        layer.n = static_cast<int>(p);
        layer.depth = planes_[p].depth;
        for (int s : types_.types[static_cast<std::size_t>(planes_[p].type)].sites)
            layer.sites.push_back(site_values(s, planes_[p].depth, false));
        layer.eps_rho = layer.sites[0].eps_rho;
        layer.eps_gradp = layer.sites[0].eps_gradp;
        layer.neighbours = layer.sites[0].neighbours;
        layers.push_back(layer);
    }
    return layers;
}

void SurfaceSums::require_finite(const std::vector<LayerErrors>& layers) const
{
    for (const auto& l : layers)
        for (const auto& v : l.sites)
            if (!std::isfinite(v.eps_rho) || !std::isfinite(v.eps_gradp)) {
                for (const auto& j : neighbours_of(v.site)) {
                    if (!std::isfinite(kernel_.w(j.r / k_, dim_, k_)))
                        fail_non_finite_kernel(kernel_, "W", j.r / k_, dim_, k_);
                    if (!std::isfinite(kernel_.dw(j.r / k_, dim_, k_)))
                        fail_non_finite_kernel(kernel_, "dW/dr", j.r / k_, dim_, k_);
                }
                fail_input("k = " + std::to_string(k_) + " gives non-finite surface errors (expected k of order 1)");
            }
}

LayerErrors SurfaceSums::bulk(int top_site) const
{
    LayerErrors bulk;
    bulk.n = -1;
    bulk.depth = INFINITY;
    for (int s = 0; s < static_cast<int>(neighbours_.size()); ++s) bulk.sites.push_back(site_values(s, 0, true));
    const auto& top = bulk.sites[static_cast<std::size_t>(top_site)];
    bulk.eps_rho = top.eps_rho;
    bulk.eps_gradp = top.eps_gradp;
    bulk.neighbours = top.neighbours;
    return bulk;
}

} // namespace

SurfaceProfile surface_profile(const Kernel& kernel, const Lattice& lattice, int site, double a_p,
                               const Eigen::Vector3d& gravity, double k, int min_layers, GradientForm form,
                               std::optional<int> termination)
{
    require_surface_inputs(kernel, lattice, site, k, min_layers);
    const Eigen::Vector3d e = gravity.stableNormalized();
    require_usable_kernel(kernel, lattice.dimension, k);
    const double reach = kernel.support() * k;

    SurfaceProfile profile;
    profile.planes = surface_planes(lattice, e);
    profile.spacing = profile.planes.period;
    profile.termination = top_plane_type(profile.planes, lattice, site, termination);
    const double period = profile.planes.period;

    // The occupied planes below the top, deep enough for the reported planes and their
    // neighbours' densities. A plane deeper than the reach has every neighbour; with
    // Monaghan's form its neighbours need theirs too (a period more than the reach again,
    // as a whole number of periods).
    const double reported_depth =
        form == GradientForm::monaghan ? reach + (std::floor(reach / period + 1e-9) + 1) * period : reach;
    const double deepest = reported_depth + reach + (min_layers + 1) * period;
    const SurfaceSums sums(kernel, lattice, profile.planes,
                           planes_below_top(profile.planes, profile.termination, deepest), a_p, e, k, form);
    profile.layers = sums.layers(reported_depth, min_layers);
    sums.require_finite(profile.layers);
    profile.bulk = sums.bulk(profile.layers[0].sites[0].site);
    for (int s = 0; s < lattice.sites(); ++s)
        profile.first_moments.push_back(HydrostaticErrors(kernel, lattice, s, a_p, e, k).tensor(k).first_moment);
    return profile;
}

} // namespace sphkern
