// The particle sets: every kernel of the study on each source, over the section's N_H or eta.
#include "study/sections/sections.hpp"

#include "particles/poisson_reference.hpp"
#include "relax/relaxation.hpp"
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

// Every kernel of the study that supports the set's dimension, on one source.
void analyse_source(const Study& study, const StudyInputs& inputs, const StudyParticleSource& s, const ParticleSet& set,
                    StudyResults& results)
{
    ParticleRequest request;
    request.sweep = study.particles->sweep;
    request.volume = study.particles->volume;
    request.vectors = false; // the study keeps statistics only
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
            auto answer = analyse_particles(kernel, set, request);
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
