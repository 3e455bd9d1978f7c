#include "requests/assess_glass.hpp"

#include "particles/particle_analysis.hpp"
#include "particles/sources/poisson_particles.hpp"
#include "relax/relaxation.hpp"

#include <cmath>

namespace sphkern {

GlassAtSetting glass_at(const Kernel& kernel, int dimension, double h_over_l, const SmoothingSpec& measure,
                        std::size_t count, double gamma, int threads)
{
    GlassAtSetting glass;
    glass.particles = count, glass.h_over_l = h_over_l;
    const ParticleSet start =
        poisson_particles({dimension, count, Eigen::Vector3d::Ones(), 1}, worker_threads(threads));
    RelaxSettings settings;
    settings.steps = glass_max_steps, settings.gamma = gamma, settings.threads = threads;
    settings.settle_steps = glass_settle_steps;
    const double l = std::pow(1.0 / static_cast<double>(count), 1.0 / dimension);
    const RelaxResult run = relax_particles(kernel, start, h_over_l * l, settings);
    glass.steps = static_cast<int>(run.history.size()) - 1, glass.settled = run.stop == "settled";
    glass.poisson_rms_e0 = run.history.front().rms_e0;
    ParticleRequest request;
    request.smoothing = measure;
    request.volume = VolumeModel::uniform;
    request.threads = threads;
    request.vectors = false;
    const ParticleAnswer answer = analyse_particles(kernel, run.state.set, request);
    for (const auto& [name, summary] : answer.points.front().statistics) {
        if (name == "e0") glass.e0 = summary;
        if (name == "eps_gradp") glass.eps_gradp = summary;
    }
    return glass;
}

} // namespace sphkern
