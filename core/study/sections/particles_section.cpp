// The particle sets: every kernel of the study on each source, over the section's N_H or eta.
#include "study/sections/sections.hpp"

#include "particles/poisson_reference.hpp"
#include "relax/relaxation.hpp"
#include "requests/particles_request.hpp"
#include "requests/relax_request.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <spdlog/spdlog.h>


namespace sphkern {

namespace {

// The source relaxed by the study kernel it names (resolved with the study's inputs).
ParticleSet relaxed(const Study& study, const Kernel& kernel, const StudyParticleSource& s, ParticleSet set)
{
    const StudyRelax& r = *s.relax;
    return at_source(study_source(study, r.json_path), [&] {
        const double h = relax_h(r.smoothing, set, kernel, smoothing_sources(FrontEnd::python));
        spdlog::info("particles: relaxing {} with {}", s.label, kernel.label());
        return relax_particles(kernel, std::move(set), h, r.settings).state.set;
    });
}

// The section's sweep and volumes as the particle request takes them (statistics only), each
// named by its JSON Pointer.
ParticleRequest particle_request_of(const Study& study, const Kernel& kernel, const ParticleSet& set)
{
    const StudyParticles& p = *study.particles;
    ParticleArguments given;
    const bool nh = p.sweep.rule == SmoothingRule::nh;
    (nh ? given.nh_range : given.eta_range) = std::array<double, 2>{p.sweep.from, p.sweep.to};
    given.steps = p.sweep.steps;
    if (p.volume) given.volume = volume_model_name(*p.volume);
    ParticleSources sources = particle_sources(FrontEnd::python);
    auto at = [&](const std::string& key) { return study_source(study, p.json_path + key); };
    sources.nh_range = at("/nh"), sources.eta_range = at("/eta"), sources.volume = at("/volume");
    sources.steps = at(nh ? "/nh/steps" : "/eta/steps");
    return particle_request(given, kernel, set, sources);
}

// Every kernel of the study that supports the set's dimension, on one source.
void analyse_source(const Study& study, const StudyInputs& inputs, const StudyParticleSource& s, const ParticleSet& set,
                    StudyResults& results)
{
    for (const auto& kernel : inputs.kernels) {
        if (!kernel.supports(set.dimension)) continue;
        throw_if_interrupted();
        spdlog::info("particles: {} on {}", kernel.label(), s.label);
        ParticlesCase c;
        c.source = s.label;
        c.kernel_label = kernel.label();
        c.dimension = set.dimension;
        c.particles = set.size();
        at_source(study_source(study, s.json_path), [&] {
            auto answer = analyse_particles(kernel, set, particle_request_of(study, kernel, set));
            c.volume = answer.volume;
            c.points = std::move(answer.points);
            for (const auto& p : c.points)
                c.poisson_rms_e0.push_back(poisson_rms_e0(kernel, set.dimension, p.eta, p.eta, set.size()));
        });
        results.particles.push_back(std::move(c));
    }
}

} // namespace

void run_particles_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    if (!study.particles) return;
    const auto& sources = study.particles->sources;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        if (const auto kernel = inputs.relax_kernel[i])
            analyse_source(study, inputs, sources[i], relaxed(study, inputs.kernels[*kernel], sources[i], inputs.particle_sets[i]),
                           results);
        else
            analyse_source(study, inputs, sources[i], inputs.particle_sets[i], results);
    }
}

} // namespace sphkern
