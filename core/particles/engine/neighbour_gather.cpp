#include "particles/engine/neighbour_gather.hpp"

#include "kernels/kernel.hpp"
#include "support/error.hpp"
#include "support/vector_clones.hpp"

#include <fmt/format.h>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define SPHKERN_HAVE_AVX512_COMPRESS 1
#define SPHKERN_HAVE_AVX2_COMPRESS 1
#endif

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace sphkern {

void Neighbours::reserve(std::size_t n)
{
    if (dx.size() >= n) return;
    const std::size_t size = std::max(n, 2 * dx.size());
    for (auto* v : {&r2, &dx, &dy, &dz, &r, &q, &a, &b, &w, &dw, &inv_r, &slot}) v->resize(size);
    index.resize(size);
}

namespace {

// The points of one run with 0 < r2 <= reach2 (and, each pair once, key > min_key), appended
// at `m` of every output array; `zeros` counts the points at r2 = 0 (the point itself, or a
// duplicate; each pair once, those with key > min_key: duplicates only).
struct RunInput {
    const double *x, *y, *z, *a, *b;
    std::size_t n;
    double xi, yi, zi, reach2;
    const double* key = nullptr;
    double min_key = 0;
};
struct Compacted {
    double *dx, *dy, *dz, *r2, *a, *b;
    std::uint32_t* index; // room for the AVX2 pass's indices of the points kept
    double* slot;         // each pair once: the place of each point kept among the run's
};

// Branch-free: every point is written, and the count moves on only for those inside.
// Without b (with_b false), the b arrays are not touched; without r2 (with_r2 false), r2 is not.
template <bool with_b, bool with_r2, bool half>
std::size_t append_within_scalar(const RunInput& in, Compacted out, std::size_t m, std::size_t& zeros)
{
    // Local copies: the compiler need not reload them after every store.
    const double* __restrict x = in.x;
    const double* __restrict y = in.y;
    const double* __restrict z = in.z;
    const double* __restrict a = in.a, * __restrict b = in.b;
    double* __restrict dx = out.dx, * __restrict dy = out.dy, * __restrict dz = out.dz;
    double* __restrict r2_out = out.r2, * __restrict va = out.a, * __restrict vb = out.b;
    const double* __restrict key = in.key;
    double* __restrict slot = out.slot;
    std::size_t at_zero = 0;
    for (std::size_t c = 0; c < in.n; ++c) {
        const double ex = x[c] - in.xi, ey = y[c] - in.yi, ez = z[c] - in.zi;
        const double r2 = ex * ex + ey * ey + ez * ez;
        dx[m] = ex, dy[m] = ey, dz[m] = ez;
        if (a) va[m] = a[c];
        if constexpr (with_r2) r2_out[m] = r2;
        if constexpr (with_b) vb[m] = b[c];
        bool later = true;
        if constexpr (half) slot[m] = static_cast<double>(c), later = key[c] > in.min_key;
        at_zero += r2 == 0 && later;
        m += r2 <= in.reach2 && r2 > 0 && later;
    }
    zeros += at_zero;
    return m;
}

#ifdef SPHKERN_HAVE_AVX512_COMPRESS
// Eight points at a time: compress in registers, then a full store (a compressing store to
// memory is slow on some processors); the outputs have room for eight more.
template <bool with_b, bool with_r2, bool half>
__attribute__((target("avx512f"))) std::size_t append_within_avx512(const RunInput& in, Compacted out, std::size_t m,
                                                                    std::size_t& zeros)
{
    const double *x = in.x, *y = in.y, *z = in.z, *a = in.a, *b = in.b;
    double *dx = out.dx, *dy = out.dy, *dz = out.dz, *r2_out = out.r2, *va = out.a, *vb = out.b;
    const std::size_t n = in.n;
    const __m512d xi = _mm512_set1_pd(in.xi), yi = _mm512_set1_pd(in.yi), zi = _mm512_set1_pd(in.zi);
    const __m512d reach2 = _mm512_set1_pd(in.reach2), zero = _mm512_setzero_pd(), min_key = _mm512_set1_pd(in.min_key);
    unsigned at_zero = 0;
    for (std::size_t c = 0; c < n; c += 8) {
        __mmask8 live = n - c >= 8 ? __mmask8(0xff) : __mmask8((1u << (n - c)) - 1);
        [[maybe_unused]] __m512d keys = zero;
        if constexpr (half)
            keys = _mm512_maskz_loadu_pd(live, in.key + c), live &= _mm512_cmp_pd_mask(keys, min_key, _CMP_GT_OQ);
        const __m512d ex = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, x + c), xi);
        const __m512d ey = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, y + c), yi);
        const __m512d ez = _mm512_sub_pd(_mm512_maskz_loadu_pd(live, z + c), zi);
        const __m512d r2 =
            _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey)), _mm512_mul_pd(ez, ez));
        const __mmask8 zeros_here = _mm512_mask_cmp_pd_mask(live, r2, zero, _CMP_EQ_OQ);
        const __mmask8 inside = _mm512_mask_cmp_pd_mask(live, r2, reach2, _CMP_LE_OQ) & __mmask8(~zeros_here);
        at_zero += static_cast<unsigned>(std::popcount(static_cast<unsigned>(zeros_here)));
        _mm512_storeu_pd(dx + m, _mm512_maskz_compress_pd(inside, ex));
        _mm512_storeu_pd(dy + m, _mm512_maskz_compress_pd(inside, ey));
        _mm512_storeu_pd(dz + m, _mm512_maskz_compress_pd(inside, ez));
        if constexpr (with_r2) _mm512_storeu_pd(r2_out + m, _mm512_maskz_compress_pd(inside, r2));
        if (a) _mm512_storeu_pd(va + m, _mm512_maskz_compress_pd(inside, _mm512_maskz_loadu_pd(live, a + c)));
        if constexpr (with_b)
            _mm512_storeu_pd(vb + m, _mm512_maskz_compress_pd(inside, _mm512_maskz_loadu_pd(live, b + c)));
        if constexpr (half) {
            const __m512d slots =
                _mm512_add_pd(_mm512_set1_pd(static_cast<double>(c)), _mm512_setr_pd(0, 1, 2, 3, 4, 5, 6, 7));
            _mm512_storeu_pd(out.slot + m, _mm512_maskz_compress_pd(inside, slots));
        }
        m += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(inside)));
    }
    zeros += at_zero;
    return m;
}
#endif

#ifdef SPHKERN_HAVE_AVX2_COMPRESS
// AVX2 has no compress: the lanes whose mask bit is set are moved to the front by a
// permutation of eight 32-bit halves, one table row per mask; a lane is `width` halves (two
// for four doubles, one for eight indices).
template <int lanes, int width>
struct CompressTable {
    alignas(32) std::int32_t row[1 << lanes][8];
    constexpr CompressTable() : row{}
    {
        for (int mask = 0; mask < 1 << lanes; ++mask) {
            int to = 0;
            for (int lane = 0; lane < lanes; ++lane)
                if (mask >> lane & 1)
                    for (int half = 0; half < width; ++half) row[mask][to++] = width * lane + half;
        }
    }
};
inline constexpr CompressTable<4, 2> compress_table{};
inline constexpr CompressTable<8, 1> index_compress_table{};

__attribute__((target("avx2"))) inline __m256d compress4(__m256d v, __m256i order)
{
    return _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(v), order));
}

// The first `left` (at most four) lanes live.
__attribute__((target("avx2"))) inline __m256i live_lanes(std::size_t left)
{
    const std::int64_t k = left >= 4 ? 4 : static_cast<std::int64_t>(left);
    return _mm256_cmpgt_epi64(_mm256_set1_epi64x(k), _mm256_setr_epi64x(0, 1, 2, 3));
}

// The mask of four r2 at most reach2 (near) and of those at 0.
__attribute__((target("avx2"))) inline void near_and_zero(const double* x, const double* y, const double* z, __m256d xi,
                                                          __m256d yi, __m256d zi, __m256d reach2, unsigned& near,
                                                          unsigned& zero)
{
    const __m256d ex = _mm256_sub_pd(_mm256_loadu_pd(x), xi);
    const __m256d ey = _mm256_sub_pd(_mm256_loadu_pd(y), yi);
    const __m256d ez = _mm256_sub_pd(_mm256_loadu_pd(z), zi);
    const __m256d r2 =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ex, ex), _mm256_mul_pd(ey, ey)), _mm256_mul_pd(ez, ez));
    near = static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(r2, reach2, _CMP_LE_OQ)));
    zero = static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(r2, _mm256_setzero_pd(), _CMP_EQ_OQ)));
}

// The mask of four keys above min_key.
__attribute__((target("avx2"))) inline unsigned keys_above(const double* key, __m256d min_key)
{
    return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(key), min_key, _CMP_GT_OQ)));
}

// As append_within_avx512, in two steps: the indices of the points inside, eight candidates
// at a time (a 32-bit permutation per mask: AVX2 moves eight indices as cheaply as four
// doubles), then x_j - x_i and the values of just those points. The inputs have room for
// eight more points than in.n (a cluster's candidates), the outputs too.
template <bool with_b, bool with_r2, bool half>
__attribute__((target("avx2"))) std::size_t append_within_avx2(const RunInput& in, Compacted out, std::size_t m,
                                                               std::size_t& zeros)
{
    const __m256d xi = _mm256_set1_pd(in.xi), yi = _mm256_set1_pd(in.yi), zi = _mm256_set1_pd(in.zi);
    const __m256d reach2 = _mm256_set1_pd(in.reach2), min_key = _mm256_set1_pd(in.min_key);
    std::uint32_t* index = out.index;
    std::size_t kept = 0;
    unsigned at_zero = 0;
    const __m256i step = _mm256_set1_epi32(8);
    __m256i ids = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (std::size_t c = 0; c < in.n; c += 8, ids = _mm256_add_epi32(ids, step)) {
        unsigned near_lo, zero_lo, near_hi, zero_hi;
        near_and_zero(in.x + c, in.y + c, in.z + c, xi, yi, zi, reach2, near_lo, zero_lo);
        near_and_zero(in.x + c + 4, in.y + c + 4, in.z + c + 4, xi, yi, zi, reach2, near_hi, zero_hi);
        unsigned live = in.n - c >= 8 ? 0xffu : (1u << (in.n - c)) - 1;
        if constexpr (half) live &= keys_above(in.key + c, min_key) | keys_above(in.key + c + 4, min_key) << 4;
        const unsigned zero = (zero_lo | zero_hi << 4) & live, inside = (near_lo | near_hi << 4) & live & ~zero;
        at_zero += static_cast<unsigned>(std::popcount(zero));
        const __m256i order = _mm256_load_si256(reinterpret_cast<const __m256i*>(index_compress_table.row[inside]));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(index + kept), _mm256_permutevar8x32_epi32(ids, order));
        kept += static_cast<std::size_t>(std::popcount(inside));
    }
    zeros += at_zero;
    // Local copies: the compiler need not reload them after every store.
    const double* __restrict x = in.x, * __restrict y = in.y, * __restrict z = in.z;
    const double* __restrict a = in.a, * __restrict b = in.b;
    const double x0 = in.xi, y0 = in.yi, z0 = in.zi;
    double* __restrict dx = out.dx + m, * __restrict dy = out.dy + m, * __restrict dz = out.dz + m;
    double* __restrict r2 = out.r2 + m, * __restrict va = out.a + m, * __restrict vb = out.b + m;
    const std::uint32_t* __restrict kept_index = index;
    for (std::size_t j = 0; j < kept; ++j) {
        const std::uint32_t k = kept_index[j];
        const double ex = x[k] - x0, ey = y[k] - y0, ez = z[k] - z0;
        dx[j] = ex, dy[j] = ey, dz[j] = ez;
        if constexpr (with_r2) r2[j] = ex * ex + ey * ey + ez * ez;
        if (a) va[j] = a[k];
        if constexpr (with_b) vb[j] = b[k];
        if constexpr (half) out.slot[m + j] = static_cast<double>(k);
    }
    return m + kept;
}
#endif

using AppendWithin = std::size_t (*)(const RunInput&, Compacted, std::size_t, std::size_t&);

// The widest path the processor has, or a narrower one a test chose.
CompressPath& chosen_path()
{
    static CompressPath path = widest_compress_path();
    return path;
}

template <bool with_b, bool with_r2, bool half>
AppendWithin append_within_for(CompressPath path)
{
    switch (path) {
#ifdef SPHKERN_HAVE_AVX512_COMPRESS
    case CompressPath::avx512: return append_within_avx512<with_b, with_r2, half>;
#endif
#ifdef SPHKERN_HAVE_AVX2_COMPRESS
    case CompressPath::avx2: return append_within_avx2<with_b, with_r2, half>;
#endif
    default: return append_within_scalar<with_b, with_r2, half>;
    }
}

template <bool half>
AppendWithin append_within_for(CompressPath path, bool with_b, bool with_r2)
{
    return with_b
               ? (with_r2 ? append_within_for<true, true, half>(path) : append_within_for<true, false, half>(path))
               : (with_r2 ? append_within_for<false, true, half>(path) : append_within_for<false, false, half>(path));
}

[[noreturn]] void fail_duplicate(const NeighbourGrid& grid, std::size_t p, const std::string& set_name)
{
    // The pair the search counted: its squared distance is 0, whether or not the positions are equal.
    const double at[3] = {grid.x()[p], grid.y()[p], grid.z()[p]};
    for (std::size_t j = 0; j < grid.points(); ++j) {
        const double d[3] = {grid.x()[j] - at[0], grid.y()[j] - at[1], grid.z()[j] - at[2]};
        if (j != p && d[0] * d[0] + d[1] * d[1] + d[2] * d[2] == 0)
            fail_coincident(set_name, grid.id(p), grid.id(j), at, d);
    }
    throw std::logic_error("a duplicate position that is not there");
}

} // namespace

void fail_coincident(const std::string& set_name, std::uint64_t i, std::uint64_t k, const double* at, const double* d)
{
    const auto first = std::min(i, k), second = std::max(i, k);
    if (d[0] == 0 && d[1] == 0 && d[2] == 0)
        throw CoincidentParticles(fmt::format("{}: particles {} and {} are at the same position ({:g}, {:g}, {:g})",
                                              set_name, first, second, at[0], at[1], at[2]),
                                  first, second);
    throw CoincidentParticles(
        fmt::format("{}: particles {} and {} are {:g} apart, too close for their squared distance "
                    "to be a number (it underflows to 0); expected distinct positions",
                    set_name, first, second, std::hypot(d[0], d[1], d[2])),
        first, second);
}

CompressPath widest_compress_path()
{
#ifdef SPHKERN_HAVE_AVX512_COMPRESS
    if (__builtin_cpu_supports("avx512f")) return CompressPath::avx512;
#endif
#ifdef SPHKERN_HAVE_AVX2_COMPRESS
    if (__builtin_cpu_supports("avx2")) return CompressPath::avx2;
#endif
    return CompressPath::scalar;
}

void use_compress_path(CompressPath path)
{
    if (path > widest_compress_path()) throw std::logic_error("this processor cannot take that path");
    chosen_path() = path;
}

void require_alone(const NeighbourGrid& grid, std::size_t p, std::size_t zeros, const std::string& set_name)
{
    if (zeros == 0) throw std::logic_error("a particle is not among its own candidates");
    if (zeros > 1) fail_duplicate(grid, p, set_name);
}

void ClusterCandidates::reserve(std::size_t n)
{
    if (x.size() >= n) return;
    const std::size_t size = std::max(n, 2 * x.size());
    for (auto* v : {&x, &y, &z, &a, &b, &key}) v->resize(size);
}

namespace {

// The points of one run within sqrt(reach2) of the box [lo, hi], appended at m; branch-free.
std::size_t append_near_box_scalar(const RunInput& in, const double* lo, const double* hi, ClusterCandidates& out,
                                   std::size_t m)
{
    const double* __restrict x = in.x, * __restrict y = in.y, * __restrict z = in.z;
    const double* __restrict a = in.a, * __restrict b = in.b;
    double* __restrict ox = out.x.data(), * __restrict oy = out.y.data(), * __restrict oz = out.z.data();
    double* __restrict oa = out.a.data(), * __restrict ob = out.b.data(), * __restrict okey = out.key.data();
    for (std::size_t c = 0; c < in.n; ++c) {
        const double ex = std::max({0.0, lo[0] - x[c], x[c] - hi[0]});
        const double ey = std::max({0.0, lo[1] - y[c], y[c] - hi[1]});
        const double ez = std::max({0.0, lo[2] - z[c], z[c] - hi[2]});
        ox[m] = x[c], oy[m] = y[c], oz[m] = z[c];
        if (a) oa[m] = a[c];
        if (b) ob[m] = b[c];
        if (in.key) okey[m] = in.key[c];
        m += ex * ex + ey * ey + ez * ez <= in.reach2 && (!in.key || in.key[c] > in.min_key);
    }
    return m;
}

#ifdef SPHKERN_HAVE_AVX512_COMPRESS
// As append_within_avx512: eight points at a time, compressed in registers, full stores
// (the outputs have room for eight more).
__attribute__((target("avx512f"))) std::size_t append_near_box_avx512(const RunInput& in, const double* lo,
                                                                      const double* hi, ClusterCandidates& out,
                                                                      std::size_t m)
{
    const double *x = in.x, *y = in.y, *z = in.z, *a = in.a, *b = in.b;
    double *ox = out.x.data(), *oy = out.y.data(), *oz = out.z.data(), *oa = out.a.data(), *ob = out.b.data();
    const __m512d zero = _mm512_setzero_pd(), reach2 = _mm512_set1_pd(in.reach2);
    const __m512d lx = _mm512_set1_pd(lo[0]), ly = _mm512_set1_pd(lo[1]), lz = _mm512_set1_pd(lo[2]);
    const __m512d hx = _mm512_set1_pd(hi[0]), hy = _mm512_set1_pd(hi[1]), hz = _mm512_set1_pd(hi[2]);
    for (std::size_t c = 0; c < in.n; c += 8) {
        const __mmask8 live = in.n - c >= 8 ? __mmask8(0xff) : __mmask8((1u << (in.n - c)) - 1);
        const __m512d px = _mm512_maskz_loadu_pd(live, x + c), py = _mm512_maskz_loadu_pd(live, y + c);
        const __m512d pz = _mm512_maskz_loadu_pd(live, z + c);
        // How far outside [lo, hi] along each axis (0 inside); maskz_max, as plain max reads an
        // undefined register that GCC 12 warns about.
        const __mmask8 all = 0xff;
        const __m512d ex =
            _mm512_maskz_max_pd(all, _mm512_maskz_max_pd(all, zero, _mm512_sub_pd(lx, px)), _mm512_sub_pd(px, hx));
        const __m512d ey =
            _mm512_maskz_max_pd(all, _mm512_maskz_max_pd(all, zero, _mm512_sub_pd(ly, py)), _mm512_sub_pd(py, hy));
        const __m512d ez =
            _mm512_maskz_max_pd(all, _mm512_maskz_max_pd(all, zero, _mm512_sub_pd(lz, pz)), _mm512_sub_pd(pz, hz));
        const __m512d d2 =
            _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey)), _mm512_mul_pd(ez, ez));
        __mmask8 inside = _mm512_mask_cmp_pd_mask(live, d2, reach2, _CMP_LE_OQ);
        if (in.key) {
            const __m512d keys = _mm512_maskz_loadu_pd(live, in.key + c);
            inside &= _mm512_cmp_pd_mask(keys, _mm512_set1_pd(in.min_key), _CMP_GT_OQ);
            _mm512_storeu_pd(out.key.data() + m, _mm512_maskz_compress_pd(inside, keys));
        }
        _mm512_storeu_pd(ox + m, _mm512_maskz_compress_pd(inside, px));
        _mm512_storeu_pd(oy + m, _mm512_maskz_compress_pd(inside, py));
        _mm512_storeu_pd(oz + m, _mm512_maskz_compress_pd(inside, pz));
        if (a) _mm512_storeu_pd(oa + m, _mm512_maskz_compress_pd(inside, _mm512_maskz_loadu_pd(live, a + c)));
        if (b) _mm512_storeu_pd(ob + m, _mm512_maskz_compress_pd(inside, _mm512_maskz_loadu_pd(live, b + c)));
        m += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(inside)));
    }
    return m;
}
#endif

#ifdef SPHKERN_HAVE_AVX2_COMPRESS
// As append_near_box_avx512, four points at a time.
__attribute__((target("avx2"))) std::size_t append_near_box_avx2(const RunInput& in, const double* lo, const double* hi,
                                                                 ClusterCandidates& out, std::size_t m)
{
    const double *x = in.x, *y = in.y, *z = in.z, *a = in.a, *b = in.b;
    double *ox = out.x.data(), *oy = out.y.data(), *oz = out.z.data(), *oa = out.a.data(), *ob = out.b.data();
    const __m256d zero = _mm256_setzero_pd(), reach2 = _mm256_set1_pd(in.reach2);
    const __m256d lx = _mm256_set1_pd(lo[0]), ly = _mm256_set1_pd(lo[1]), lz = _mm256_set1_pd(lo[2]);
    const __m256d hx = _mm256_set1_pd(hi[0]), hy = _mm256_set1_pd(hi[1]), hz = _mm256_set1_pd(hi[2]);
    for (std::size_t c = 0; c < in.n; c += 4) {
        const __m256i live = live_lanes(in.n - c);
        const __m256d px = _mm256_maskload_pd(x + c, live), py = _mm256_maskload_pd(y + c, live);
        const __m256d pz = _mm256_maskload_pd(z + c, live);
        const __m256d ex = _mm256_max_pd(_mm256_max_pd(zero, _mm256_sub_pd(lx, px)), _mm256_sub_pd(px, hx));
        const __m256d ey = _mm256_max_pd(_mm256_max_pd(zero, _mm256_sub_pd(ly, py)), _mm256_sub_pd(py, hy));
        const __m256d ez = _mm256_max_pd(_mm256_max_pd(zero, _mm256_sub_pd(lz, pz)), _mm256_sub_pd(pz, hz));
        const __m256d d2 =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ex, ex), _mm256_mul_pd(ey, ey)), _mm256_mul_pd(ez, ez));
        unsigned inside = static_cast<unsigned>(_mm256_movemask_pd(_mm256_castsi256_pd(live))) &
                          static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(d2, reach2, _CMP_LE_OQ)));
        __m256d keys = _mm256_setzero_pd();
        if (in.key) {
            keys = _mm256_maskload_pd(in.key + c, live);
            inside &=
                static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(keys, _mm256_set1_pd(in.min_key), _CMP_GT_OQ)));
        }
        const __m256i order = _mm256_load_si256(reinterpret_cast<const __m256i*>(compress_table.row[inside]));
        if (in.key) _mm256_storeu_pd(out.key.data() + m, compress4(keys, order));
        _mm256_storeu_pd(ox + m, compress4(px, order));
        _mm256_storeu_pd(oy + m, compress4(py, order));
        _mm256_storeu_pd(oz + m, compress4(pz, order));
        if (a) _mm256_storeu_pd(oa + m, compress4(_mm256_maskload_pd(a + c, live), order));
        if (b) _mm256_storeu_pd(ob + m, compress4(_mm256_maskload_pd(b + c, live), order));
        m += static_cast<std::size_t>(std::popcount(inside));
    }
    return m;
}
#endif

using AppendNearBox = std::size_t (*)(const RunInput&, const double*, const double*, ClusterCandidates&, std::size_t);

AppendNearBox append_near_box_for(CompressPath path)
{
    switch (path) {
#ifdef SPHKERN_HAVE_AVX512_COMPRESS
    case CompressPath::avx512: return append_near_box_avx512;
#endif
#ifdef SPHKERN_HAVE_AVX2_COMPRESS
    case CompressPath::avx2: return append_near_box_avx2;
#endif
    default: return append_near_box_scalar;
    }
}

} // namespace

void gather_cluster(const NeighbourGrid& grid, std::size_t c, PointValues reach, const double* a, const double* b,
                    ClusterCandidates& out, const PairOrder* order)
{
    const AppendNearBox append_near_box = append_near_box_for(chosen_path());
    out.count = 0, out.reach = 0, out.with_a = a != nullptr, out.with_b = b != nullptr, out.with_key = order != nullptr;
    out.any_unpaired = false;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    bool any = false;
    std::size_t first = 0; // the cluster's first visited point
    for (std::size_t p = grid.cluster_begin(c); p < grid.cluster_end(c); ++p) {
        if (!grid.visited(p)) continue;
        const double at[3] = {grid.x()[p], grid.y()[p], grid.z()[p]};
        for (int d = 0; d < 3; ++d)
            lo[d] = any ? std::min(lo[d], at[d]) : at[d], hi[d] = any ? std::max(hi[d], at[d]) : at[d];
        out.reach = std::max(out.reach, reach[p]);
        if (!any) first = p;
        any = true;
    }
    if (!any) return;
    // A hair wider than any particle's reach2: the box distance rounds no larger than r.
    RunInput in{nullptr, nullptr, nullptr, nullptr, nullptr, 0, 0, 0, 0, out.reach * out.reach * (1 + 1e-12)};
    // Each pair once: no particle of the cluster takes a candidate whose key is not above its own.
    in.min_key = static_cast<double>(first);
    std::size_t m = 0;
    grid.for_each_run_near_box(lo, hi, out.reach, [&](std::size_t begin, std::size_t end) {
        if (order) { // the visited points before the cluster's first take their pairs from their side
            const std::size_t cut = std::min(end, first);
            if (begin < cut && order->unpaired_before[cut] == order->unpaired_before[begin]) begin = cut;
            if (begin == end) return;
            out.any_unpaired = out.any_unpaired || order->unpaired_before[end] > order->unpaired_before[begin];
        }
        in.n = end - begin;
        in.x = grid.x() + begin, in.y = grid.y() + begin, in.z = grid.z() + begin, in.a = a ? a + begin : nullptr;
        in.b = b ? b + begin : nullptr, in.key = order ? order->keys.data() + begin : nullptr;
        out.reserve(m + in.n + neighbour_lanes);
        m = append_near_box(in, lo, hi, out, m);
    });
    out.count = m;
}

std::size_t compress_run(const double* const* xyz, const double* a, const double* b, std::size_t n, const double* at,
                         double reach2, Neighbours& nb, std::size_t& zeros)
{
    const AppendWithin append = append_within_for<false>(chosen_path(), b != nullptr, true);
    const RunInput in{xyz[0], xyz[1], xyz[2], a, b, n, at[0], at[1], at[2], reach2};
    nb.reserve(n + neighbour_lanes);
    return append(in,
                  {nb.dx.data(), nb.dy.data(), nb.dz.data(), nb.r2.data(), nb.a.data(), nb.b.data(), nb.index.data(),
                   nb.slot.data()},
                  0, zeros);
}

void gather_from_cluster(const NeighbourGrid& grid, const ClusterCandidates& cluster, std::size_t p, double reach2,
                         const std::string& set_name, Neighbours& nb, bool with_r2)
{
    const CompressPath path = chosen_path();
    const bool half = cluster.with_key;
    const AppendWithin append = half ? append_within_for<true>(path, cluster.with_b, with_r2)
                                     : append_within_for<false>(path, cluster.with_b, with_r2);
    const RunInput in{cluster.x.data(),   cluster.y.data(),
                      cluster.z.data(),   cluster.with_a ? cluster.a.data() : nullptr,
                      cluster.b.data(),   cluster.count,
                      grid.x()[p],        grid.y()[p],
                      grid.z()[p],        reach2,
                      cluster.key.data(), static_cast<double>(p)};
    nb.reserve(cluster.count + neighbour_lanes);
    std::size_t zeros = 0;
    const std::size_t m = append(in,
                                 {nb.dx.data(), nb.dy.data(), nb.dz.data(), nb.r2.data(), nb.a.data(), nb.b.data(),
                                  nb.index.data(), nb.slot.data()},
                                 0, zeros);
    // Each pair once, p itself is not among the candidates kept, and a point at r = 0 is a duplicate.
    if (half && zeros > 0) fail_duplicate(grid, p, set_name);
    if (!half) require_alone(grid, p, zeros, set_name);
    for (std::size_t j = m; j < m + neighbour_lanes; ++j)
        nb.dx[j] = nb.dy[j] = nb.dz[j] = nb.a[j] = nb.b[j] = 0, nb.r2[j] = reach2,
        nb.slot[j] = static_cast<double>(cluster.count);
    nb.count = m;
}

PairOrder::PairOrder(const NeighbourGrid& grid) : keys(grid.points()), unpaired_before(grid.points() + 1)
{
    for (std::size_t p = 0; p < keys.size(); ++p) {
        keys[p] = grid.visited(p) ? static_cast<double>(p) : unpaired_key(grid);
        unpaired_before[p + 1] = unpaired_before[p] + (grid.visited(p) ? 0 : 1);
    }
}

double search_reach(double support_radius) { return support_radius * std::sqrt(1 + 2 * support_edge); }

SPHKERN_ENGINE_CLONES void distances(Neighbours& nb, std::size_t padded, double inv_h)
{
    const double* __restrict dx = nb.dx.data(), * __restrict dy = nb.dy.data(), * __restrict dz = nb.dz.data();
    double* __restrict q = nb.q.data(), * __restrict inv_r = nb.inv_r.data();
    for (std::size_t j = 0; j < padded; ++j) {
        const double r = std::sqrt(dx[j] * dx[j] + dy[j] * dy[j] + dz[j] * dz[j]);
        q[j] = r * inv_h;
        inv_r[j] = 1.0 / r;
    }
    for (std::size_t j = nb.count; j < padded; ++j) q[j] = inv_r[j] = 0;
}

SPHKERN_ENGINE_CLONES void fill_distances(Neighbours& nb)
{
    const double* __restrict r2 = nb.r2.data();
    double* __restrict r = nb.r.data();
    for (std::size_t j = 0; j < nb.count; ++j) r[j] = std::sqrt(r2[j]);
}

SPHKERN_ENGINE_CLONES void scale_distances(const double* __restrict r, std::size_t n, double factor,
                                           double* __restrict q)
{
    for (std::size_t j = 0; j < n; ++j) q[j] = r[j] * factor;
}

} // namespace sphkern
