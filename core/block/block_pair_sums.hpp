// The block's two sums over one particle's gathered neighbours (nb, in the pair pass's
// padding): the density sum of W and the gradient sum of the hydrostatic pressure in each
// gradient form, each in eight lanes added in a fixed order, so that they vectorise and give
// the same bits on any thread count. The block's sweep and its floor benchmark call them.
#pragma once

#include "analysis/gradient_form.hpp"
#include "particles/engine/neighbour_gather.hpp"

#include <cstddef>

namespace sphkern {

// The sum of W (w) over the `live` neighbours of `padded`.
double block_density_sum(const double* w, std::size_t padded, std::size_t live);

// The sum of weight_ij W'(r) (x_i - x_j) . e / r over the `padded` neighbours, with W' in
// nb.dw, 1 / r in nb.inv_r (0 past the live ones) and, for Monaghan's form, rho_j in nb.b;
// weight_ij is the form's for P = rho0 g depth, depth_j = depth_i + e . (x_j - x_i).
double block_gradient_sum(GradientForm form, double depth_i, double rho_i, const Neighbours& nb, const double* e,
                          std::size_t padded);

} // namespace sphkern
