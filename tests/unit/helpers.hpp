// Shared test helpers: the shipped kernels by name, and an independent brute-force
// sum over lattice points that does not use the shell code.
#pragma once

#include "kernels/kernel.hpp"
#include "kernels/kernel_registry.hpp"
#include "lattices/lattice.hpp"
#include "support/error.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

namespace sphkern::test {

// The message and exit code of what f throws; an empty message and ExitCode::ok if nothing.
template <class F>
std::pair<std::string, ExitCode> refusal(F&& f)
{
    try {
        f();
    } catch (const Error& e) {
        return {e.what(), e.code()};
    }
    return {"", ExitCode::ok};
}

inline KernelRegistry& shipped_kernels()
{
    // The build tree's plugins (SPHKERN_PLUGIN_PATH, set by the tests' main).
    static KernelRegistry registry = KernelRegistry::discover({});
    return registry;
}

inline Kernel shipped_kernel(const std::string& name) { return Kernel(shipped_kernels().find(name)); }

// A lattice file by name: the examples shipped with sphkern (lattices/examples), else the
// test data (tests/data/lattices).
inline std::string lattice_file(const std::string& name)
{
    const std::string example = SPHKERN_SOURCE_DIR "/lattices/examples/" + name + ".json";
    return std::filesystem::exists(example) ? example : SPHKERN_SOURCE_DIR "/tests/data/lattices/" + name + ".json";
}

struct BruteForce {
    double eps_rho, eps_gradp;
};

// eps_rho and eps_gradP by summing W over every lattice point in a large box,
// truncating at R (share/docs/method.md section 2, written out directly).
inline BruteForce brute_force_errors(const Kernel& kernel, const Lattice& lattice, double k, double a_p,
                                     const Eigen::Vector3d& e)
{
    const int dim = lattice.dimension, n = 12;
    const double R = kernel.support();
    double density = kernel.w(0, dim, k), gradient = 0;
    for (const auto& site : lattice.motif)
        for (int a = -n; a <= n; ++a)
            for (int b = -n; b <= n; ++b)
                for (int c = (dim == 3 ? -n : 0); c <= (dim == 3 ? n : 0); ++c) {
                    Eigen::Vector3d x = lattice.basis * (Eigen::Vector3d(a, b, c) + site - lattice.motif[0]);
                    double r = x.norm();
                    if (r < 1e-12 || r / k > R * (1 + 1e-12)) continue; // the support edge is inside
                    density += kernel.w(r / k, dim, k);
                    gradient += std::pow(e.dot(x), 2) / r * kernel.dw(r / k, dim, k);
                }
    return {a_p * density / std::pow(k, dim) - 1, -a_p * gradient / std::pow(k, dim + 1) - 1};
}

} // namespace sphkern::test
