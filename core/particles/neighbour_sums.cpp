#include "particles/neighbour_sums.hpp"

#include "support/vector_clones.hpp"

namespace sphkern {

namespace {

// Eight lanes of partial sums per quantity, as two vectors of four in GCC's vector type:
// the accumulators stay in registers (an array of them was kept in memory, a load and a store
// per term; a vector of eight is split badly where registers hold four), and every lane adds
// in the same order on every instruction set, so the sums are the same bits on any machine. A
// pass takes only as many quantities as sixteen AVX2 registers hold.
using Quad = double __attribute__((vector_size(4 * sizeof(double))));
using UnalignedQuad = double __attribute__((vector_size(4 * sizeof(double)), aligned(alignof(double))));
static_assert(neighbour_lanes == 8);
struct Partial {
    Quad lo = {}, hi = {};
};
const UnalignedQuad* as_quads(const double* p) { return reinterpret_cast<const UnalignedQuad*>(p); }

double total_of(const Partial& p)
{
    return p.lo[0] + p.lo[1] + p.lo[2] + p.lo[3] + p.hi[0] + p.hi[1] + p.hi[2] + p.hi[3];
}

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
    // Quad q of the neighbours adds to lanes 0 to 3 when q is even, 4 to 7 when it is odd.
    auto add = [](Partial& p, std::size_t q, const Quad& term) { (q % 2 ? p.hi : p.lo) += term; };
    for (std::size_t q = 0; q < quads; ++q) { // the values and their first moments
        const Quad vw = (uniform_volume ? v_all : v[q]) * w[q];
        add(a0, q, vw), add(a2, q, vw * dx[q]), add(a3, q, vw * dy[q]), add(a4, q, vw * dz[q]);
        if constexpr (with_mass) add(a1, q, m[q] * w[q]);
    }
    total[s0] = total_of(a0), total[sm] = total_of(a1);
    total[m1x] = total_of(a2), total[m1y] = total_of(a3), total[m1z] = total_of(a4);
    // grad_i W_ij = -W'(r) r_ij / r: g collects -V_j W' / r.
    a0 = a1 = a2 = Partial{};
    for (std::size_t q = 0; q < quads; ++q) { // the gradient of a constant
        const Quad g = -(uniform_volume ? v_all : v[q]) * dw[q] * inv_r[q];
        add(a0, q, g * dx[q]), add(a1, q, g * dy[q]), add(a2, q, g * dz[q]);
    }
    total[e1x] = total_of(a0), total[e1y] = total_of(a1), total[e1z] = total_of(a2);
    a0 = a1 = a2 = Partial{};
    for (std::size_t q = 0; q < quads; ++q) { // E in the plane of x and y
        const Quad g = -(uniform_volume ? v_all : v[q]) * dw[q] * inv_r[q], x = dx[q], y = dy[q];
        add(a0, q, g * x * x), add(a1, q, g * y * y), add(a2, q, g * x * y);
    }
    total[exx] = total_of(a0), total[eyy] = total_of(a1), total[exy] = total_of(a2);
    a0 = a1 = a2 = Partial{};
    for (std::size_t q = 0; in.with_z && q < quads; ++q) { // E's terms with z, zero in 2D
        const Quad g = -(uniform_volume ? v_all : v[q]) * dw[q] * inv_r[q], z = dz[q];
        add(a0, q, g * z * z), add(a1, q, g * dx[q] * z), add(a2, q, g * dy[q] * z);
    }
    total[ezz] = total_of(a0), total[exz] = total_of(a1), total[eyz] = total_of(a2);
}

} // namespace

void neighbour_sums(Neighbours& nb, std::size_t padded, double uniform_volume, bool with_mass, bool with_z,
                    double* total)
{
    const PairArrays in{nb.dx.data(), nb.dy.data(), nb.dz.data(),  nb.inv_r.data(), nb.a.data(),
                        with_mass ? nb.b.data() : nullptr,           nb.w.data(),     nb.dw.data(),
                        uniform_volume, padded,       with_z};
    if (uniform_volume > 0) {
        for (std::size_t j = nb.count; j < padded; ++j) nb.w[j] = nb.dw[j] = 0; // no V_j = 0 on the padding
        if (with_mass) sums_over<true, true>(in, total);
        else sums_over<false, true>(in, total);
    } else if (with_mass)
        sums_over<true, false>(in, total);
    else
        sums_over<false, false>(in, total);
}

} // namespace sphkern
