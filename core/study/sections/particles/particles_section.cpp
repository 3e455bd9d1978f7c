#include "study/sections/particles/particles_section.hpp"

#include "codes/code_table.hpp"
#include "particles/particles_memory.hpp"
#include "particles/poisson_reference.hpp"
#include "relax/relaxation.hpp"
#include "requests/particles_request.hpp"
#include "requests/relax_request.hpp"
#include "requests/source_request.hpp"
#include "study/study.hpp"
#include "study/study_inputs.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/process/progress.hpp"
#include "support/process/work_budget.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace sphkern {

namespace {

constexpr double max_particle_evaluations = 1e8; // particles x N_H values, over all sources

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

// The section's sweep, or its code's setting, and its volumes as a request's arguments.
ParticleArguments arguments_of(const StudyParticles& p)
{
    ParticleArguments given;
    if (p.code) name_code(given, p.code->name, p.code->value);
    else {
        const bool nh = p.sweep.rule == SmoothingRule::nh;
        (nh ? given.nh_range : given.eta_range) = std::array<double, 2>{p.sweep.from, p.sweep.to};
        given.steps = p.sweep.steps;
    }
    if (p.volume) given.volume = volume_model_name(*p.volume);
    return given;
}

// The section's sweep and volumes as the particle request takes them (statistics only), each
// named by its JSON Pointer.
ParticleRequest particle_request_of(const StudyParticles& p, const Study& study, const Kernel& kernel,
                                    const ParticleSet& set)
{
    ParticleArguments given = arguments_of(p);
    ParticleSources sources = particle_sources(FrontEnd::python);
    auto at = [&](const std::string& key) { return study_source(study, p.json_path + key); };
    sources.nh_range = at("/nh"), sources.eta_range = at("/h_over_l"), sources.volume = at("/volume");
    sources.steps = at(p.sweep.rule == SmoothingRule::nh ? "/nh/steps" : "/h_over_l/steps");
    if (p.code)
        sources.code = {at("/code/name"), at("/code/" + code_profile(p.code->name, sources.code.code).parameter)};
    return particle_request(given, kernel, set, sources);
}

// One kernel on one source (left out, with a warning, where the study's code does not ship it).
void analyse_case(const StudyParticles& p, const Study& study, const StudyParticleSource& s, const ParticleSet& set,
                  const Kernel& kernel, ParticlesResults& results)
{
    const CodeProfile* code = p.code ? &code_profile(p.code->name, ValueSource::argument("code")) : nullptr;
    if (code && !code->user_kernels && !code_ships(*code, kernel, set.dimension)) {
        spdlog::warn("particles: {} does not ship {}; it is left out of {}", p.code->name, kernel.label(), s.label);
        return;
    }
    throw_if_interrupted();
    spdlog::info("particles: {} on {}", kernel.label(), s.label);
    ParticlesCase c;
    c.source = s.label;
    c.kernel_label = kernel.label();
    c.dimension = set.dimension;
    c.particles = set.measured(); // a PySPH file's first array: its others are neighbours only
    at_source(study_source(study, s.json_path), [&] {
        auto answer = analyse_particles(kernel, set, particle_request_of(p, study, kernel, set));
        c.volume = answer.volume;
        if (p.code) {
            const auto given = arguments_of(p);
            c.code = given.code ? code_answer_text(*given.code)
                                : stored_code_text(*given.stored_h_code, kernel, set.dimension);
        }
        c.points = std::move(answer.points);
        for (const auto& p : c.points)
            c.poisson_rms_e0.push_back(poisson_rms_e0(kernel, set.dimension, p.eta, p.eta, set.measured()));
    });
    results.cases.push_back(std::move(c));
}

// Every kernel of the study that supports the set's dimension, on one source.
void analyse_source(const StudyParticles& p, const Study& study, const StudyInputs& inputs,
                    const StudyParticleSource& s, const ParticleSet& set, ParticlesResults& results, Progress& progress)
{
    for (const auto& kernel : inputs.kernels) {
        if (kernel.supports(set.dimension)) analyse_case(p, study, s, set, kernel, results);
        progress.step(kernel.label() + " on " + s.label);
    }
}

// What the section needs: each source read (a bad file is refused before any section runs)
// and the kernel that relaxes it. All sets are held at once, so their count together is
// bounded by the memory budget (a source that is relaxed counts twice: it is relaxed in a copy).
struct ResolvedSources {
    std::vector<ParticleSet> sets;
    std::vector<std::optional<std::size_t>> relax_kernel; // [source]: an index into the study's kernels
};

ResolvedSources resolve_sources(const StudyParticles& particles, const Study& study, const StudyInputs& inputs)
{
    ResolvedSources r;
    std::size_t total = 0;
    for (const auto& s : particles.sources) {
        r.sets.push_back(at_source(study_source(study, s.json_path),
                                   [&] { return load_source(s.source, source_sources(FrontEnd::python), 0); }));
        total += r.sets.back().size() * (s.relax ? 2 : 1);
        if (total > max_particles())
            study_source(study, s.json_path)
                .fail("the particle sources up to this one hold " + std::to_string(total) +
                      " particles (a relaxed one counted twice), more than the " + std::to_string(max_particles()) +
                      " the memory budget allows (three quarters of the available memory)");
    }
    for (const auto& s : particles.sources) { // "relax" names a study kernel by its label or name
        auto& index = r.relax_kernel.emplace_back();
        if (!s.relax) continue;
        const auto& k = inputs.kernels;
        const auto it = std::find_if(k.begin(), k.end(), [&](const Kernel& kernel) {
            return kernel.label() == s.relax->kernel || kernel.name() == s.relax->kernel;
        });
        if (it == k.end()) {
            std::vector<std::string> labels;
            for (const auto& kernel : k) labels.push_back(kernel.label());
            study_source(study, s.relax->json_path)
                .fail("kernel: \"" + s.relax->kernel + "\" is not one of the study's kernels" +
                      did_you_mean(s.relax->kernel, labels));
        }
        index = static_cast<std::size_t>(it - k.begin());
    }
    return r;
}

// A sweep's smallest h is its sparsest point: a particle without a neighbour there is refused
// now, with the error the run would give, not after the sections before this one have run.
// Only that point is measured, per source and kernel. A code's setting is one point, the
// section's whole work, and a relaxed source is known only once relaxed: both are left to the run.
void check_smallest_h(const StudyParticles& p, const Study& study, const StudyInputs& inputs, const ResolvedSources& r)
{
    if (p.code) return;
    for (std::size_t i = 0; i < p.sources.size(); ++i) {
        if (p.sources[i].relax) continue;
        const ParticleSet& set = r.sets[i];
        for (const auto& kernel : inputs.kernels) {
            if (!kernel.supports(set.dimension)) continue;
            at_source(study_source(study, p.sources[i].json_path), [&] {
                ParticleRequest request = particle_request_of(p, study, kernel, set);
                if (!request.sweep) return;
                request.smoothing = {request.sweep->rule, std::min(request.sweep->from, request.sweep->to), 0};
                request.sweep.reset();
                request.vectors = false;
                analyse_particles(kernel, set, request);
            });
        }
    }
}

class ParticlesSection : public StudySection {
public:
    explicit ParticlesSection(StudyParticles particles) : particles_(std::move(particles)) {}

    void check_budget(const Study& study, const JsonNode& root) const override
    {
        const double evaluations = double(study.kernels.size()) * study_particle_evaluations(particles_);
        if (evaluations > max_particle_evaluations)
            root.error("the study " + over_budget("kernels x particles x N_H values, over all particle sources",
                                                  evaluations, max_particle_evaluations));
    }

    SectionRun resolve(const Study& study, KernelRegistry&, StudyInputs& inputs) const override
    {
        auto sources = std::make_shared<const ResolvedSources>(resolve_sources(particles_, study, inputs));
        check_smallest_h(particles_, study, inputs, *sources);
        return [p = particles_, sources](const Study& study, const StudyInputs& inputs, const StudyResults&) {
            auto results = std::make_shared<ParticlesResults>();
            Progress progress("particles", p.sources.size() * inputs.kernels.size(), part_scope(inputs, "particles"));
            for (std::size_t i = 0; i < p.sources.size(); ++i) {
                const ParticleSet& set = sources->sets[i];
                if (const auto kernel = sources->relax_kernel[i])
                    analyse_source(p, study, inputs, p.sources[i],
                                   relaxed(study, inputs.kernels[*kernel], p.sources[i], set), *results, progress);
                else analyse_source(p, study, inputs, p.sources[i], set, *results, progress);
            }
            return std::shared_ptr<const SectionResults>(results);
        };
    }

private:
    StudyParticles particles_;
};

} // namespace

std::shared_ptr<const StudySection> read_particles_section(const JsonNode& node,
                                                           const std::filesystem::path& study_file)
{
    return std::make_shared<ParticlesSection>(read_study_particles(node, study_file));
}

} // namespace sphkern
