// Free-surface layer profiles (share/docs/method.md section 6): the errors of a particle on
// layer n below a free surface normal to gravity, by lattice sums over the half-space.
#pragma once

#include "analysis/gradient_form.hpp"
#include "analysis/hydrostatic_errors.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// The lattice planes normal to gravity, occupied as they are. They repeat every
// `period` (the smallest positive projection of a lattice vector on gravity); within one
// period each plane type holds the motif sites whose projections coincide, at `offset`.
// A termination is the plane type on top. A single-site lattice has one type, and its
// planes are equally spaced by the period.
struct PlaneType {
    double offset = 0;      // in [0, period), d
    std::vector<int> sites; // motif sites on planes of this type
};

struct SurfacePlanes {
    double period = 0;
    std::vector<PlaneType> types; // by offset
    int type_of_site(int site) const;
    std::string name(int type) const; // "sites 0,2"
};

// Throws Error(input) if gravity is not normal to a family of lattice planes.
SurfacePlanes surface_planes(const Lattice& lattice, const Eigen::Vector3d& gravity);

struct SiteLayerErrors {
    int site = 0;
    double eps_rho = 0;
    double eps_gradp = 0;
    int neighbours = 0; // inside the support, excluding the particle
};

struct LayerErrors {
    int n = 0;
    double depth = 0;   // below the top plane, in d
    double eps_rho = 0; // the plane's first site
    double eps_gradp = 0;
    int neighbours = 0;
    std::vector<SiteLayerErrors> sites; // every site on the plane
};

struct SurfaceProfile {
    double spacing = 0; // the planes' period (the layer spacing of a one-site lattice)
    SurfacePlanes planes;
    int termination = 0;             // the plane type on top
    std::vector<LayerErrors> layers; // the occupied planes, n = 0 (top) downwards, until the bulk is reached
    LayerErrors bulk;                // every neighbour present (first site, then every site)
    // First moments per site (see GradientTensor): where one is not zero the sum form's
    // bulk value depends on depth (2 P_i m1); the bulk row leaves that term out.
    std::vector<Eigen::Vector3d> first_moments;
};

inline constexpr int max_surface_layers = 10000; // of min_layers

// Planes 0 .. max(min_layers, the first plane whose neighbourhood and whose neighbours'
// neighbourhoods are complete) - 1. The termination is the plane type holding `site`,
// unless `termination` names one (an index into planes.types).
SurfaceProfile surface_profile(const Kernel& kernel, const Lattice& lattice, int site, double a_p,
                               const Eigen::Vector3d& gravity, double k, int min_layers, GradientForm form,
                               std::optional<int> termination = std::nullopt);

} // namespace sphkern
