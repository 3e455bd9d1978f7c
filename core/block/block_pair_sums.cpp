#include "block/block_pair_sums.hpp"

#include "particles/engine/symmetric_pair_pass.hpp"
#include "support/vector_clones.hpp"

#include <algorithm>
#include <type_traits>

namespace sphkern {

namespace {

constexpr std::size_t lanes = neighbour_lanes;

// The sum of W over the `live` neighbours, in eight lanes added in a fixed order.
SPHKERN_ENGINE_CLONES double density_sum(const double* __restrict w, std::size_t n, std::size_t live)
{
    double acc[lanes] = {};
    for (std::size_t base = 0; base < n; base += lanes)
        for (std::size_t l = 0; l < lanes; ++l) acc[l] += base + l < live ? w[base + l] : 0.0;
    double t = 0;
    for (double a : acc) t += a;
    return t;
}

// The sum of weight_ij W'(r) (x_i - x_j) . e / r over the `padded` neighbours, with
// (x_i - x_j) . e = -height, height = e . (x_j - x_i), and the weight of each form for
// P = rho0 g depth (inv_r = 0 past the live neighbours). Gravity is normal to the lateral
// sides, so a neighbour's depth is depth_i + height, through a periodic side too: it is not
// gathered.
template <GradientForm form>
SPHKERN_ENGINE_CLONES double gradient_sum(double depth_i, double rho_i, const Neighbours& nb, const double* e,
                                          std::size_t n)
{
    const double* __restrict dx = nb.dx.data(), * __restrict dy = nb.dy.data(), * __restrict dz = nb.dz.data();
    const double* __restrict rho_j = nb.b.data(), * __restrict dw = nb.dw.data(), * __restrict inv_r = nb.inv_r.data();
    double acc[lanes] = {};
    for (std::size_t base = 0; base < n; base += lanes)
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::size_t j = base + l;
            const double height = e[0] * dx[j] + e[1] * dy[j] + e[2] * dz[j];
            const double rj = form == GradientForm::monaghan ? rho_j[j] : 1.0;
            const double weight = gradient_form_weight<form>(depth_i, depth_i + height, rho_i, rj);
            acc[l] += weight * dw[j] * -height * inv_r[j];
        }
    double t = 0;
    for (double a : acc) t += a;
    return t;
}

// Each pair once: p's gradient sum over its later neighbours (returned) and, in `theirs`, each
// neighbour's term of the pair, weight_ji W'(r) (x_j - x_i) . e / r.
template <GradientForm form>
SPHKERN_ENGINE_CLONES double paired_gradient_sum(double depth_i, double rho_i, const Neighbours& nb, const double* e,
                                                 std::size_t n, double* __restrict theirs)
{
    const double* __restrict dx = nb.dx.data(), * __restrict dy = nb.dy.data(), * __restrict dz = nb.dz.data();
    const double* __restrict rho_j = nb.b.data(), * __restrict dw = nb.dw.data(), * __restrict inv_r = nb.inv_r.data();
    double acc[lanes] = {};
    for (std::size_t base = 0; base < n; base += lanes)
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::size_t j = base + l;
            const double height = e[0] * dx[j] + e[1] * dy[j] + e[2] * dz[j], depth_j = depth_i + height;
            const double rj = form == GradientForm::monaghan ? rho_j[j] : 1.0;
            const double slope = dw[j] * height * inv_r[j];
            acc[l] -= gradient_form_weight<form>(depth_i, depth_j, rho_i, rj) * slope;
            theirs[j] = gradient_form_weight<form>(depth_j, depth_i, rj, rho_i) * slope;
        }
    double t = 0;
    for (double a : acc) t += a;
    return t;
}

} // namespace

void add_block_pair_terms(std::optional<GradientForm> form, double depth_i, double rho_i, Neighbours& nb,
                          const double* e, std::size_t padded, double* own, double* cluster_sums)
{
    own[0] += density_sum(nb.w.data(), padded, nb.count);
    double* theirs = nb.q.data(); // q is spent once W' is known
    if (!form) {
        std::fill(theirs, theirs + padded, 0.0);
        add_to_pairs<2>(nb, {nb.w.data(), theirs}, cluster_sums);
        return;
    }
    auto call = [&](auto f) { return paired_gradient_sum<decltype(f)::value>(depth_i, rho_i, nb, e, padded, theirs); };
    own[1] += *form == GradientForm::sum ? call(std::integral_constant<GradientForm, GradientForm::sum>{})
              : *form == GradientForm::difference
                  ? call(std::integral_constant<GradientForm, GradientForm::difference>{})
                  : call(std::integral_constant<GradientForm, GradientForm::monaghan>{});
    add_to_pairs<2>(nb, {nb.w.data(), theirs}, cluster_sums);
}

double block_density_sum(const double* w, std::size_t padded, std::size_t live) { return density_sum(w, padded, live); }

double block_gradient_sum(GradientForm form, double depth_i, double rho_i, const Neighbours& nb, const double* e,
                          std::size_t padded)
{
    auto call = [&](auto f) { return gradient_sum<decltype(f)::value>(depth_i, rho_i, nb, e, padded); };
    switch (form) {
    case GradientForm::sum: return call(std::integral_constant<GradientForm, GradientForm::sum>{});
    case GradientForm::difference: return call(std::integral_constant<GradientForm, GradientForm::difference>{});
    case GradientForm::monaghan: break;
    }
    return call(std::integral_constant<GradientForm, GradientForm::monaghan>{});
}

} // namespace sphkern
