// The particle sets: every kernel of the study on each source, over the section's N_H or eta.
#include "study/sections/sections.hpp"

#include "lattices/lattice.hpp"
#include "particles/poisson_reference.hpp"
#include "relax/relaxation.hpp"
#include "support/error.hpp"
#include "support/interruption.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>

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

// The source relaxed by the study kernel it names (its label or name).
ParticleSet relaxed(const Study& study, const StudyInputs& inputs, const StudyParticleSource& s, ParticleSet set)
{
    const StudyRelax& r = *s.relax;
    const auto kernel = std::find_if(inputs.kernels.begin(), inputs.kernels.end(),
                                     [&](const Kernel& k) { return k.label() == r.kernel || k.name() == r.kernel; });
    try {
        if (kernel == inputs.kernels.end())
            fail_input(fmt::format("kernel: \"{}\" is not one of the study's kernels", r.kernel));
        if (!set.box) fail_input("relaxation needs a periodic box");
        const double h = smoothing_lengths(set, *kernel, r.smoothing, mean_volume(set)).front();
        spdlog::info("particles: relaxing {} with {}", s.label, kernel->label());
        return relax_particles(*kernel, std::move(set), h, r.settings).state.set;
    } catch (const Error& e) {
        throw Error(e.code(), study.file + ": " + r.json_path + ": " + e.what());
    }
}

} // namespace

void run_particles_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    if (!study.particles) return;
    const auto& section = *study.particles;
    for (const auto& s : section.sources) {
        ParticleSet set = load_source(study, s);
        if (s.relax) set = relaxed(study, inputs, s, std::move(set));
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
                for (const auto& p : c.points)
                    c.poisson_rms_e0.push_back(poisson_rms_e0(kernel, set.dimension, p.eta, p.eta, set.size()));
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": " + s.json_path + ": " + e.what());
            }
            results.particles.push_back(std::move(c));
        }
    }
}

} // namespace sphkern
