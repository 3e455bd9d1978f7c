#include "requests/stability_request.hpp"

#include "stability/dispersion.hpp"
#include "stability/stability_json.hpp"

#include <algorithm>
#include <thread>

namespace sphkern {

void check_stability_request(const StabilityRequest& r, const StabilitySources& sources)
{
    if (r.mode == StabilityMode::over_k)
        check_k_interval(r.k_min, r.k_max, sources.k_min, sources.k_max);
    else
        check_k(r.k, sources.k, sources.k_hint);
    check_gamma(r.gamma, sources.gamma.name);
    check_horizon(r.horizon, sources.horizon.name);
}

nlohmann::json run_stability(const StabilityRequest& r, const StabilitySources& sources, const Kernel& kernel,
                             const Lattice& lattice)
{
    const int threads = r.threads > 0 ? r.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    switch (r.mode) {
    case StabilityMode::path:
        return dispersion_path_document(kernel, lattice, r.k, r.gamma, r.path_points, r.h_model);
    case StabilityMode::wavevector: {
        const auto kappa = checked_wavevector(r.wavevector, lattice.dimension, sources.wavevector.name);
        return dispersion_document(kernel, lattice, r.k, r.gamma, kappa, r.h_model);
    }
    case StabilityMode::over_k:
        return stability_over_k_document(kernel, lattice, r.k_min, r.k_max, r.steps, r.gamma, r.grid, threads,
                                         r.horizon, r.h_model);
    case StabilityMode::zone_scan: break;
    }
    return stability_document(kernel, lattice, r.k, r.gamma, r.grid, threads, r.horizon, r.h_model);
}

} // namespace sphkern
