// The particle sets: every kernel of the study on each source, over the section's N_H or eta.
#include "study/sections/sections.hpp"

#include "lattices/lattice.hpp"
#include "support/error.hpp"
#include "support/interruption.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace sphkern {

namespace {

ParticleSet load_source(const Study& study, const StudyParticleSource& s)
{
    try {
        if (s.source.kind == SourceKind::lattice) {
            const int dim = load_lattice(s.source.spec).dimension;
            if (static_cast<int>(s.sizes) != dim)
                fail_input(fmt::format("size: the lattice is {}D, expected {} cell counts", dim, dim));
        }
        return load_particles(s.source);
    } catch (const Error& e) {
        throw Error(e.code(), study.file + ": " + s.json_path + ": " + e.what());
    }
}

} // namespace

void run_particles_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    if (!study.particles) return;
    const auto& section = *study.particles;
    for (const auto& s : section.sources) {
        const ParticleSet set = load_source(study, s);
        ParticleRequest request;
        request.sweep = section.sweep;
        request.volume = section.volume;
        for (const auto& kernel : inputs.kernels) {
            if (!kernel.supports(set.dimension)) continue;
            throw_if_interrupted();
            spdlog::info("particles: {} on {}", kernel.label(), s.label);
            ParticlesCase c;
            c.source = s.label;
            c.kernel_label = kernel.label();
            c.dimension = set.dimension;
            c.particles = set.size();
            try {
                auto answer = analyse_particles(kernel, set, request);
                c.volume = answer.volume;
                c.points = std::move(answer.points);
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": " + s.json_path + ": " + e.what());
            }
            results.particles.push_back(std::move(c));
        }
    }
}

} // namespace sphkern
