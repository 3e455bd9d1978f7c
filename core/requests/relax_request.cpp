#include "requests/relax_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "codes/code_table.hpp"
#include "codes/swift/swift_gamma.hpp"
#include "codes/swift/swift_kernels.hpp"
#include "particles/density_smoothing.hpp"
#include "particles/particle_volumes.hpp"
#include "particles/particles_memory.hpp"
#include "particles/poisson_reference.hpp"
#include "relax/glass_quality.hpp"
#include "requests/particles_request.hpp"
#include "support/error.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace sphkern {

RelaxSources relax_sources(FrontEnd f)
{
    auto n = [f](const char* key) { return value_named(f, key); };
    return {smoothing_sources(f), n("method"), n("steps"),    n("tolerance"), n("gamma"),   n("dt"),
            n("damping"),         n("alpha"),  n("max_move"), n("threads"),   n("rdf_max"), n("rdf_bins")};
}

RelaxMethod relax_method_of(const std::string& name, const ValueSource& source)
{
    if (name == "pressure") return RelaxMethod::pressure;
    if (name == "shift") return RelaxMethod::shift;
    source.fail(fmt::format("\"{}\" is unknown, expected pressure or shift", name), ErrorKind::unknown_name);
}

void check_relax_settings(const RelaxSettings& s, const RelaxSources& sources)
{
    const SettingTable& declared = settings_of("relax");
    check_setting(declared["steps"], s.steps, sources.steps);
    check_setting(declared["tolerance"], s.tolerance, sources.tolerance);
    check_setting(declared["gamma"], s.gamma, sources.gamma);
    check_setting(declared["dt"], s.time_step, sources.dt);
    check_setting(declared["damping"], s.damping, sources.damping);
    check_setting(declared["alpha"], s.alpha, sources.alpha);
    check_setting(declared["max_move"], s.max_move, sources.max_move);
    check_setting(declared["threads"], s.threads, sources.threads);
}

void check_rdf(double r_max, std::size_t bins, const RelaxSources& sources)
{
    check_rdf_settings(r_max, bins, sources.rdf_max, sources.rdf_bins);
}

RelaxedSet judge_relaxed(const Kernel& kernel, const RelaxResult& run, int threads, double r_max, std::size_t bins)
{
    const ParticleSet& set = run.state.set;
    RelaxedSet judged;
    judged.eta = run.h / mean_spacing(set);
    judged.nh = neighbour_number(judged.eta, kernel.support(), set.dimension);
    ParticleRequest request; // the run's own h, not a value a user gave
    request.smoothing = {SmoothingRule::eta, judged.eta, 0};
    request.volume = VolumeModel::uniform;
    request.threads = threads;
    request.vectors = false;
    judged.measures = analyse_particles(kernel, set, request);
    judged.quality = glass_quality(set, r_max, bins, worker_threads(threads));
    judged.poisson_rms_e0 = poisson_rms_e0(kernel, set.dimension, run.h / run.spacing, judged.eta, set.size());
    return judged;
}

namespace {

// Whether the written h is each particle's own, solved as the code solves it.
bool solved_h(const RelaxCode& code)
{
    return code.value && code_profile(code.name, ValueSource::argument("code")).from_sph_density;
}

} // namespace

ParticleLayout relax_layout(const std::optional<RelaxCode>& code)
{
    if (!code) return ParticleLayout::swift;
    switch (code_profile(code->name, ValueSource::argument("code")).layout) {
    case CodeLayout::gadget: return ParticleLayout::gadget;
    case CodeLayout::pysph: return ParticleLayout::pysph;
    case CodeLayout::phantom: return ParticleLayout::phantom;
    default: return ParticleLayout::swift; // a .csv output (the code's h in a column)
    }
}

void check_relax_code(const RelaxCode& code, const std::string& output, const Kernel& kernel, int dimension,
                      const CodeSettingSources& sources)
{
    const auto& profile = code_profile(code.name, sources.code);
    require_lattice_volume(profile, "a relaxation");
    const bool csv = output.ends_with(".csv"), hdf5 = output.ends_with(".h5") || output.ends_with(".hdf5");
    if (!output.empty() && !csv && profile.layout == CodeLayout::none) {
        std::vector<std::string> hdf5_codes;
        for (const auto& p : code_profiles())
            if (p.layout != CodeLayout::none && p.layout != CodeLayout::phantom) hdf5_codes.push_back(p.name);
        const std::string last = hdf5_codes.back();
        hdf5_codes.pop_back();
        sources.code.fail(
            fmt::format("{}: sphkern writes HDF5 initial conditions for {} and {}, and a Phantom dump for "
                        "phantom; {} starts from files of its own (a .csv output holds its h)",
                        code.name, fmt::join(hdf5_codes, ", "), last, profile.title));
    }
    if (hdf5 && !output.ends_with(profile.hdf5_suffix))
        sources.code.fail(fmt::format("{}: {}; expected a name ending in {}, not {}", code.name,
                                      profile.hdf5_suffix_reason, profile.hdf5_suffix, output));
    if (!code.value && output.empty())
        sources.code.fail(
            fmt::format("{}: names the code the written set is for, or with {} sets h; expected an output "
                        "or {}",
                        code.name, sources.value.name, sources.value.name));
    if (code.value) check_code_setting({code.name, *code.value}, sources);
    require_code_kernel(profile, kernel, dimension);
}

SmoothingSpec relax_code_smoothing(const RelaxCode& code, const Kernel& kernel, int dimension,
                                   const CodeSettingSources& sources)
{
    const SmoothingSpec spec = code_smoothing({code.name, *code.value}, sources, kernel, dimension);
    return {SmoothingRule::eta, spec.value, 0};
}

ParticleOutput initial_conditions(const Kernel& kernel, const ParticleSet& set, const RelaxResult& run,
                                  const InitialState& state, const std::optional<RelaxCode>& code, int threads)
{
    const double gamma_eos = state.eos_gamma;
    const double u = state.u ? *state.u : gamma_eos > 1 ? 1 / (gamma_eos * (gamma_eos - 1)) : 0;
    // The run's mass is its mean volume (unit density): rho0 times it is rho0 V.
    const double mass = state.rho0 * run.state.model.mass;
    const double volume = mean_volume(set), density = mass / volume;
    const std::size_t n = set.size();
    if (!code) {
        const double gamma = swift_gamma(kernel, set.dimension), support = kernel.support() * run.h;
        if (!(gamma > 0)) return {std::vector<double>(n, run.h), kernel.support(), mass, density, "", u};
        return {std::vector<double>(n, support / gamma), gamma, mass, density, swift_kernel_label(kernel.name()), u};
    }
    const auto& profile = code_profile(code->name, ValueSource::argument("code"));
    const double per_h = code_support_per_h(profile, kernel, set.dimension), to_stored = kernel.support() / per_h;
    ParticleOutput out{std::vector<double>(n, run.h * to_stored),
                       per_h,
                       mass,
                       density,
                       profile.layout == CodeLayout::swift ? swift_kernel_label(kernel.name()) : "",
                       u,
                       relax_layout(code)};
    if (solved_h(*code)) {
        const SmoothingSpec spec =
            code_smoothing({code->name, *code->value}, {ValueSource::argument("code"), ValueSource::argument("value")},
                           kernel, set.dimension);
        // Solved once on the run's set: copy c of it holds particle i at c n + i (tiled_set), and
        // its periodic images are the other copies, so each copy's h is the original's.
        const ParticleSet& run_set = run.state.set;
        const PerParticle h =
            density_smoothing_lengths(kernel, run_set, spec.value, mean_volume(run_set), threads, spec.by_number);
        for (std::size_t i = 0; i < n; ++i) out.h[i] = h[i % run_set.size()] * to_stored;
    }
    if (profile.layout == CodeLayout::phantom) {
        // Phantom's h = hfact (m / rho)^(1/3): with its parameter, rho is each particle's SPH
        // density (the solve above); without, the set's m / V at the run's one h.
        out.hfact = solved_h(*code) ? *code->value : out.h[0] / std::cbrt(mass / density);
        out.eos_gamma = gamma_eos;
        out.sound_speed = 1; // the relaxation's c
    }
    return out;
}

nlohmann::json relax_code_json(const RelaxCode& code)
{
    const auto& profile = code_profile(code.name, ValueSource::argument("code"));
    const char* layouts[] = {"swift", "gadget", "pysph", "phantom"};
    nlohmann::json out = {{"name", code.name},
                          {"parameter", profile.parameter},
                          {"layout", layouts[static_cast<int>(relax_layout(code))]},
                          {"written_h", solved_h(code) ? "sph_density" : "run_h"}};
    if (code.value) out["value"] = *code.value;
    return out;
}

std::string relax_code_text(const RelaxCode& code)
{
    const auto& profile = code_profile(code.name, ValueSource::argument("code"));
    const std::string setting = code.value ? fmt::format(" {} = {:.10g}", profile.parameter, *code.value) : "";
    return fmt::format("for {}{}: {}", code.name, setting,
                       solved_h(code)
                           ? "the run's h at the rest density; each written h solved with the particle's SPH density"
                           : "written with the run's h in the code's convention");
}

void check_code_beside_h(const RelaxCode& code, bool h_given, FrontEnd f, const CodeSettingSources& sources)
{
    if (!code.value || !h_given) return;
    throw Error(sources.code.code,
                fmt::format("{} {} sets h with {}; expected no {}, {} or {} beside it", sources.code.name, code.name,
                            sources.value.name, value_named(f, "h_over_l").name, value_named(f, "nh").name,
                            value_named(f, "k").name));
}

void check_relax_output(const std::string& file, const ValueSource& source, const std::optional<RelaxCode>& code)
{
    // An unknown code is left to check_relax_code, which names --code.
    bool phantom = false;
    for (const auto& p : code_profiles())
        phantom = phantom || (code && p.name == code->name && p.layout == CodeLayout::phantom);
    try {
        check_particle_output_name(file, phantom ? ParticleLayout::phantom : ParticleLayout::swift);
    } catch (const Error& e) { // "--output x.txt: expected ...", "output x.txt: expected ..."
        const std::string hint = phantom ? "" : " (with --code phantom, any other name: a Phantom full dump)";
        throw Error(source.code, source.name + " " + e.what() + hint);
    }
}

std::array<int, 3> tiles_of(const std::string& text, const ParticleSet& set, const ValueSource& source)
{
    std::array<int, 3> tiles{1, 1, 1};
    if (text.empty()) return tiles;
    const auto counts = parse_number_list(text, source, 1, 3);
    for (std::size_t a = 0; a < counts.size(); ++a) {
        if (counts[a] != std::floor(counts[a]) || counts[a] < 1 || counts[a] > 1000)
            source.fail(fmt::format("{}: expected whole numbers of copies from 1 to 1000", text));
        tiles[a] = static_cast<int>(counts[a]);
    }
    if (static_cast<int>(counts.size()) != set.dimension)
        throw Error(ExitCode::input, fmt::format("{} {}: {} counts for a set in {} dimensions; expected {}",
                                                 source.name, text, counts.size(), set.dimension, set.dimension));
    const double copies = static_cast<double>(tiles[0]) * tiles[1] * tiles[2];
    if (copies * static_cast<double>(set.size()) > static_cast<double>(max_particles()))
        throw Error(ExitCode::input,
                    fmt::format("{} {}: {:.0f} particles, more than the memory budget holds ({})", source.name, text,
                                copies * static_cast<double>(set.size()), max_particles()));
    return tiles;
}

double relax_h(const SmoothingSpec& spec, const ParticleSet& set, const Kernel& kernel, const SmoothingSources& sources)
{
    if (!set.box)
        fail_input(
            fmt::format("{}: relaxation needs a periodic box; expected a lattice block, poisson or a file with a box",
                        set.name));
    // Walls and solids read as neighbours only would move with the fluid.
    if (set.neighbours_only)
        fail_input(fmt::format("{}: relaxation moves every particle; expected one particle array, not a list (a list "
                               "of arrays is for `particles`)",
                               set.name));
    check_smoothing_fits(spec, set, sources);
    return smoothing_lengths(set, kernel, spec, mean_volume(set))[0];
}

} // namespace sphkern
