// The cost of calling a kernel through the plugin interface: the shipped cubic_bspline
// plugin's batch and scalar functions against the same source compiled into this
// program, where the compiler can inline it.
#include "kernels/kernel.hpp"
#include "kernels/kernel_registry.hpp"

#include <benchmark/benchmark.h>

#include <cstdlib>
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

} // namespace

BENCHMARK(inline_batch);
BENCHMARK(plugin_batch);
BENCHMARK(plugin_scalar);
BENCHMARK_MAIN();
