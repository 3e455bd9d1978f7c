// Free-surface layer profiles (method.md section 6): the errors of a particle on
// layer n below a free surface normal to gravity, by lattice sums over the half-space.
#pragma once

#include "analysis/hydrostatic_errors.hpp"

#include <string>
#include <vector>

namespace sphkern {

// The pressure-gradient interpolation: sum (P_i + P_j), difference (P_j - P_i), or
// Monaghan's rho_i sum m_j (P_i / rho_i^2 + P_j / rho_j^2) with per-layer densities.
enum class GradientForm { sum, difference, monaghan };
GradientForm parse_gradient_form(const std::string& text);
const char* gradient_form_name(GradientForm form);

// The spacing of the lattice planes normal to `gravity`, in units of d; throws
// Error(input) if gravity is not normal to a family of equally spaced lattice planes.
double layer_spacing(const Lattice& lattice, int site, const Eigen::Vector3d& gravity);

struct LayerErrors {
    int n = 0;
    double depth = 0; // n * spacing, in d
    double eps_rho = 0;
    double eps_gradp = 0;
    int neighbours = 0; // inside the support, excluding the particle
};

struct SurfaceProfile {
    double spacing = 0;
    std::vector<LayerErrors> layers; // n = 0 (top) downwards, until the bulk is reached
    LayerErrors bulk;                // the same sums with every neighbour present
};

// Layers 0 .. max(min_layers, the first layer whose neighbourhood and whose
// neighbours' neighbourhoods are complete) - 1.
SurfaceProfile surface_profile(const Kernel& kernel, const Lattice& lattice, int site, double a_p,
                               const Eigen::Vector3d& gravity, double k, int min_layers, GradientForm form);

} // namespace sphkern
