// `sphkern relax`: a particle set relaxed in its periodic box (SPH pressure with damping, or
// particle shifting), the glass it makes judged and written for `sphkern particles`.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "cli/source_options.hpp"

#include "particles/particles_memory.hpp"
#include "requests/relax_run.hpp"
#include "requests/source_request.hpp"
#include "support/io/results_output.hpp"
#include "support/text/value_checks.hpp"

#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

struct RelaxOptions : CommonOptions, SourceOptions {
    std::string kernel, method, output, history, tile; // the defaults: requests/settings
    std::vector<std::string> sets;
    std::optional<double> h_over_l, eta, nh, k;
    std::optional<double> rho0, u; // of the written initial conditions
    SettingOptions codes;          // --code and the codes' parameters but --eta (SWIFT's, with --code swift)
    RelaxSettings settings;
    double memory_limit = 0, rdf_max = 0;
    std::size_t rdf_bins = 0;
};

void add_options(Command c, RelaxOptions& o)
{
    c.add_setting("kernel", o.kernel);
    add_source_options(c, o);
    c.add_setting("h_over_l", o.h_over_l);
    c.add_setting("eta", o.eta);
    c.add_setting("nh", o.nh);
    c.add_setting("k", o.k);
    c.add_setting("code", o.codes.code);
    add_code_parameters(c, o.codes);
    // The radius gives a SPlisHSPlasH file's h, which a rule for h would leave unused.
    c.get_option("--particle-radius").excludes("--h-over-l").excludes("--nh").excludes("--k");
    c.add_setting("method", o.method);
    auto& s = o.settings;
    c.add_setting("steps", s.steps);
    c.add_setting("tolerance", s.tolerance);
    c.add_setting("gamma", s.gamma);
    c.add_setting("dt", s.time_step);
    c.add_setting("damping", s.damping);
    c.add_setting("alpha", s.alpha);
    c.add_setting("max_move", s.max_move);
    c.add_setting("threads", s.threads);
    c.add_setting("rdf_max", o.rdf_max);
    c.add_setting("rdf_bins", o.rdf_bins);
    c.add_setting("memory_limit", o.memory_limit);
    c.add_setting("output", o.output);
    c.add_setting("rho0", o.rho0);
    c.add_setting("u", o.u);
    c.add_setting("tile", o.tile);
    c.add_setting("history", o.history);
    add_set_option(c, o.sets);
    add_plugin_option(c, o);
    add_json_option(c, o);
}

// --code and its setting, if given.
std::optional<RelaxCode> relax_code_of(const RelaxOptions& o)
{
    if (const auto choice = code_beside_own_eta(o.codes, o.eta)) return RelaxCode{choice->code, choice->value};
    return std::nullopt;
}

} // namespace

Action add_relax_command(Command app)
{
    Command command = app.add_subcommand("relax", "Relax a particle set into a glass and judge it");
    auto options = std::make_shared<RelaxOptions>();
    add_options(command, *options);
    return [options, command] {
        auto& o = *options;
        set_memory_budget(o.memory_limit, value_named(FrontEnd::command_line, "memory_limit"));
        const auto [code_source, value_source] = code_sources(o.codes);
        auto given_text = [&](const char* option, const std::string& text) {
            return command.count(option) ? std::optional(text) : std::nullopt;
        };
        const bool primitive_block = source_kind(o.source) == SourceKind::lattice && o.cell != "rectangular";
        const RelaxJob job = relax_job({o.h_over_l,
                                        o.nh,
                                        o.k,
                                        relax_code_of(o),
                                        {code_source, value_source},
                                        o.method,
                                        o.settings,
                                        o.rdf_max,
                                        o.rdf_bins,
                                        given_text("--output", o.output),
                                        given_text("--history", o.history),
                                        o.tile,
                                        o.rho0,
                                        o.u,
                                        primitive_block},
                                       FrontEnd::command_line, read_inputs(o.source, o.kernel, o.plugins));
        auto registry = discover_kernels(o);
        auto kernel = make_kernel(registry, o.kernel, o.sets);
        const auto digest = o.json ? start_source_digest(o) : nullptr;
        ParticleSet set = load_source(source_of(o), source_sources(FrontEnd::command_line), o.settings.threads);
        const RelaxOutcome outcome = run_relax(kernel, std::move(set), job);
        if (o.json) print_json(relax_outcome_json(kernel, job, outcome), source_inputs(o, kernel, digest.get()));
        else print_relax_outcome(results_file(), kernel, job, outcome);
        return 0;
    };
}

} // namespace sphkern::cli
