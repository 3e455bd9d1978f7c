// The cost of calling a kernel through the plugin interface: the shipped cubic_bspline
// plugin's batch and scalar functions against the same source compiled into this
// program, where the compiler can inline it. And the floors of the engine's sweeps: their
// per-pair arithmetic on neighbours that stay in L1 (the measures', the block's two sums).
#include "block/block_pair_sums.hpp"
#include "kernels/kernel.hpp"
#include "kernels/kernel_registry.hpp"
#include "particles/engine/neighbour_gather.hpp"
#include "particles/neighbour_sums.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

namespace inline_cubic_bspline {
#include "../../plugins/kernels/cubic_bspline.c"
}

namespace {

constexpr std::size_t run_length = 100; // a row of the block engine

std::vector<double> sample_q()
{
    std::vector<double> q(run_length);
    for (std::size_t i = 0; i < run_length; ++i) q[i] = 2.4 * static_cast<double>(i) / run_length;
    return q;
}

const sphkern::Kernel& plugin_kernel()
{
    static sphkern::Kernel kernel = [] {
        ::setenv("SPHKERN_PLUGIN_PATH", SPHKERN_BUILD_DIR "/plugins", 0);
        auto registry = sphkern::KernelRegistry::discover({});
        return sphkern::Kernel(registry.find("cubic_bspline"));
    }();
    return kernel;
}

void plugin_batch(benchmark::State& state)
{
    const auto& kernel = plugin_kernel();
    auto q = sample_q();
    std::vector<double> out(run_length);
    for (auto _ : state) {
        kernel.w_batch(q.data(), out.data(), run_length, 3, 1.2);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * run_length));
}

void inline_batch(benchmark::State& state)
{
    auto q = sample_q();
    std::vector<double> out(run_length);
    for (auto _ : state) {
        inline_cubic_bspline::w_batch(q.data(), out.data(), run_length, 3, 1.2, nullptr);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * run_length));
}

void plugin_scalar(benchmark::State& state)
{
    const auto& kernel = plugin_kernel();
    auto q = sample_q();
    std::vector<double> out(run_length);
    for (auto _ : state) {
        for (std::size_t i = 0; i < run_length; ++i) out[i] = kernel.w(q[i], 3, 1.2);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * run_length));
}

// One run of the fused sweep on data in L1 (distance, one sqrt and one division, the
// plugin's W and W', both sums): the most pairs per second one core can do, with no
// neighbour search and no memory traffic. BENCHMARKS.md divides the block engine's rate by it.
SPHKERN_VECTOR_CLONES void pair_arithmetic(const double* __restrict dx, const double* __restrict dy,
                                           const double* __restrict dz, double inv_k, double* __restrict q,
                                           double* __restrict height, double* __restrict inv_r, std::size_t n)
{
    for (std::size_t p = 0; p < n; ++p) {
        const double r = std::sqrt(dx[p] * dx[p] + dy[p] * dy[p] + dz[p] * dz[p]);
        q[p] = r * inv_k;
        inv_r[p] = 1.0 / r;
        height[p] = -dz[p];
    }
}

SPHKERN_VECTOR_CLONES void pair_sums(const double* __restrict w, const double* __restrict dw,
                                     const double* __restrict height, const double* __restrict inv_r,
                                     const double* __restrict depth, double* __restrict rho, double* __restrict grad,
                                     std::size_t n)
{
    for (std::size_t p = 0; p < n; ++p) {
        const bool inside = inv_r[p] >= 1.0 / 2.4;
        rho[p] += inside ? w[p] : 0.0;
        grad[p] += inside ? depth[p] * dw[p] * -height[p] * inv_r[p] : 0.0;
    }
}

// The ceiling's loop with W and W' from one call of the plugin's fused evaluation
// (sphkern.fused_evaluation.1) instead of its two batch calls; the ceiling itself is kept
// as it was, so that figures before and after the extension divide by the same thing.
template <bool one_call>
void pair_ceiling(benchmark::State& state)
{
    const auto& kernel = plugin_kernel();
    std::vector<double> dx(run_length), dy(run_length), dz(run_length), q(run_length), height(run_length),
        inv_r(run_length), w(run_length), dw(run_length), depth(run_length, 1.0), rho(run_length), grad(run_length);
    for (std::size_t i = 0; i < run_length; ++i) {
        dx[i] = 0.5 + 1.5 * static_cast<double>(i) / run_length;
        dy[i] = 0.3;
        dz[i] = -0.2;
    }
    for (auto _ : state) {
        pair_arithmetic(dx.data(), dy.data(), dz.data(), 1 / 1.2, q.data(), height.data(), inv_r.data(), run_length);
        if constexpr (one_call) kernel.w_dw_batch(q.data(), w.data(), dw.data(), run_length, 3, 1.2);
        else {
            kernel.w_batch(q.data(), w.data(), run_length, 3, 1.2);
            kernel.dw_batch(q.data(), dw.data(), run_length, 3, 1.2);
        }
        pair_sums(w.data(), dw.data(), height.data(), inv_r.data(), depth.data(), rho.data(), grad.data(), run_length);
        benchmark::DoNotOptimize(rho.data());
        benchmark::DoNotOptimize(grad.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * run_length));
}

// One particle's 78 neighbours (as many as fcc has at k = 1.2), at random inside the support
// of h = 1.2 and none at its centre; the padding after them is zero.
sphkern::Neighbours neighbours_of_fcc_count()
{
    constexpr std::size_t count = 78;
    constexpr double reach = 2 * 1.2;
    sphkern::Neighbours nb;
    nb.reserve(count + sphkern::neighbour_lanes);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-reach, reach);
    for (std::size_t j = 0; j < count;) {
        const double x = coordinate(random), y = coordinate(random), z = coordinate(random);
        const double r2 = x * x + y * y + z * z;
        if (r2 > reach * reach || r2 < 1e-6) continue;
        nb.dx[j] = x, nb.dy[j] = y, nb.dz[j] = z, ++j;
    }
    nb.count = count;
    return nb;
}

// The particle engine's own arithmetic per particle, on those neighbours in L1: r, q and
// 1 / r, the plugin's fused W and W', and the sums of the measures (sphkern particles;
// thirteen, as the set has no masses), with no neighbour search, no gather and no stores of
// results. The engine cannot do better than this per pair; BENCHMARKS.md divides its rate by it too.
void measures_pair_floor(benchmark::State& state)
{
    const auto& kernel = plugin_kernel();
    sphkern::Neighbours nb = neighbours_of_fcc_count();
    const std::size_t count = nb.count;
    constexpr double h = 1.2;
    const std::size_t padded = sphkern::padded_count(count);
    double total[sphkern::neighbour_sum_count];
    for (auto _ : state) {
        sphkern::distances(nb, padded, 1 / h);
        kernel.w_dw_batch(nb.q.data(), nb.w.data(), nb.dw.data(), padded, 3, h);
        sphkern::neighbour_sums(nb, padded, 0.7, false, true, total);
        benchmark::DoNotOptimize(total);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * count));
}

// The block's own arithmetic per particle on the same 78 neighbours in L1: r, q and 1 / r, the
// plugin's fused W and W', and its two sums (density, and the sum form's pressure gradient):
// the floor of `sphkern block`, with no neighbour search, no gather and no stores of results.
void block_pair_floor(benchmark::State& state)
{
    const auto& kernel = plugin_kernel();
    sphkern::Neighbours nb = neighbours_of_fcc_count();
    const std::size_t count = nb.count, padded = sphkern::padded_count(count);
    const double h = 1.2, e[3] = {0, 0, -1};
    double rho = 0, grad = 0;
    for (auto _ : state) {
        sphkern::distances(nb, padded, 1 / h);
        kernel.w_dw_batch(nb.q.data(), nb.w.data(), nb.dw.data(), padded, 3, h);
        rho = sphkern::block_density_sum(nb.w.data(), padded, count);
        grad = sphkern::block_gradient_sum(sphkern::GradientForm::sum, 10.0, 1.0, nb, e, padded);
        benchmark::DoNotOptimize(rho);
        benchmark::DoNotOptimize(grad);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * count));
}

void fused_pair_ceiling(benchmark::State& state) { pair_ceiling<false>(state); }
void fused_pair_ceiling_one_call(benchmark::State& state) { pair_ceiling<true>(state); }

} // namespace

BENCHMARK(fused_pair_ceiling);
BENCHMARK(fused_pair_ceiling_one_call);
BENCHMARK(measures_pair_floor);
BENCHMARK(block_pair_floor);
BENCHMARK(inline_batch);
BENCHMARK(plugin_batch);
BENCHMARK(plugin_scalar);
BENCHMARK_MAIN();
