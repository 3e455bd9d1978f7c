// The block's two sums over one particle's gathered neighbours (nb, in the pair pass's
// padding): the density sum of W and the gradient sum of the hydrostatic pressure in each
// gradient form, each in eight lanes added in a fixed order, so that they vectorise and give
// the same bits on any thread count. The block's sweep and its floor benchmark call them.
#pragma once

#include "analysis/gradient_form.hpp"
#include "particles/engine/neighbour_gather.hpp"

#include <cstddef>
#include <optional>

namespace sphkern {

// The sum of W (w) over the `live` neighbours of `padded`.
double block_density_sum(const double* w, std::size_t padded, std::size_t live);

// The sum of weight_ij W'(r) (x_i - x_j) . e / r over the `padded` neighbours, with W' in
// nb.dw, 1 / r in nb.inv_r (0 past the live ones) and, for Monaghan's form, rho_j in nb.b;
// weight_ij is the form's for P = rho0 g depth, depth_j = depth_i + e . (x_j - x_i).
double block_gradient_sum(GradientForm form, double depth_i, double rho_i, const Neighbours& nb, const double* e,
                          std::size_t padded);

// Each pair once (symmetric_pair_pass): adds p's terms over its `nb.count` later neighbours
// (W in nb.w, W' in nb.dw, 1 / r in nb.inv_r, Monaghan's rho_j in nb.b; nb.q is overwritten) to
// p's density and gradient sums, own[0] and own[1], and each pair's other terms to the
// neighbour's two in cluster_sums (add_to_pairs). Without a form, the density alone (the
// gradient's terms are 0).
void add_block_pair_terms(std::optional<GradientForm> form, double depth_i, double rho_i, Neighbours& nb,
                          const double* e, std::size_t padded, double* own, double* cluster_sums);

} // namespace sphkern
