#include "particles/neighbour_sums.hpp"

#include "particles/engine/lane_sums.hpp"
#include "support/vector_clones.hpp"

namespace sphkern {

namespace {

// A pass takes only as many quantities as sixteen AVX2 registers hold.
// The gathered arrays of one particle's neighbours, padded to a multiple of the lanes.
struct PairArrays {
    const double *dx, *dy, *dz, *inv_r, *v, *m, *w, *dw;
    double v_all; // the one volume of every particle, or 0: then v holds V_j
    std::size_t n;
    bool with_z;
};

// Without masses (m null), total[sm] stays 0: m_j = rho0 V_j, and eps_rho is e0. With one
// volume for all (uniform_volume), v is not read; the padding then needs W = W' = 0.
template <bool with_mass, bool uniform_volume>
SPHKERN_ENGINE_CLONES void sums_over(const PairArrays& in, double* __restrict total)
{
    const UnalignedQuad *dx = as_quads(in.dx), *dy = as_quads(in.dy), *dz = as_quads(in.dz);
    const UnalignedQuad *inv_r = as_quads(in.inv_r), *v = as_quads(in.v), *m = as_quads(in.m);
    const UnalignedQuad *w = as_quads(in.w), *dw = as_quads(in.dw);
    const Quad v_all = {in.v_all, in.v_all, in.v_all, in.v_all};
    const std::size_t quads = in.n / 4;
    Partial a0, a1, a2, a3, a4;
    for (std::size_t q = 0; q < quads; ++q) { // the values and their first moments
        const Quad vw = (uniform_volume ? v_all : v[q]) * w[q];
        a0.add(q, vw), a2.add(q, vw * dx[q]), a3.add(q, vw * dy[q]), a4.add(q, vw * dz[q]);
        if constexpr (with_mass) a1.add(q, m[q] * w[q]);
    }
    total[s0] = a0.total(), total[sm] = a1.total();
    total[m1x] = a2.total(), total[m1y] = a3.total(), total[m1z] = a4.total();
    // grad_i W_ij = -W'(r) r_ij / r: g collects -V_j W' / r.
    a0 = a1 = a2 = Partial{};
    for (std::size_t q = 0; q < quads; ++q) { // the gradient of a constant
        const Quad g = -(uniform_volume ? v_all : v[q]) * dw[q] * inv_r[q];
        a0.add(q, g * dx[q]), a1.add(q, g * dy[q]), a2.add(q, g * dz[q]);
    }
    total[e1x] = a0.total(), total[e1y] = a1.total(), total[e1z] = a2.total();
    a0 = a1 = a2 = Partial{};
    for (std::size_t q = 0; q < quads; ++q) { // E in the plane of x and y
        const Quad g = -(uniform_volume ? v_all : v[q]) * dw[q] * inv_r[q], x = dx[q], y = dy[q];
        a0.add(q, g * x * x), a1.add(q, g * y * y), a2.add(q, g * x * y);
    }
    total[exx] = a0.total(), total[eyy] = a1.total(), total[exy] = a2.total();
    a0 = a1 = a2 = Partial{};
    for (std::size_t q = 0; in.with_z && q < quads; ++q) { // E's terms with z, zero in 2D
        const Quad g = -(uniform_volume ? v_all : v[q]) * dw[q] * inv_r[q], z = dz[q];
        a0.add(q, g * z * z), a1.add(q, g * dx[q] * z), a2.add(q, g * dy[q] * z);
    }
    total[ezz] = a0.total(), total[exz] = a1.total(), total[eyz] = a2.total();
}

} // namespace

void neighbour_sums(Neighbours& nb, std::size_t padded, double uniform_volume, bool with_mass, bool with_z,
                    double* total)
{
    const PairArrays in{nb.dx.data(),    nb.dy.data(), nb.dz.data(),
                        nb.inv_r.data(), nb.a.data(),  with_mass ? nb.b.data() : nullptr,
                        nb.w.data(),     nb.dw.data(), uniform_volume,
                        padded,          with_z};
    if (uniform_volume > 0) {
        for (std::size_t j = nb.count; j < padded; ++j) nb.w[j] = nb.dw[j] = 0; // no V_j = 0 on the padding
        if (with_mass) sums_over<true, true>(in, total);
        else sums_over<false, true>(in, total);
    } else if (with_mass) sums_over<true, false>(in, total);
    else sums_over<false, false>(in, total);
}

} // namespace sphkern
