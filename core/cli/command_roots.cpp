// `sphkern roots`: the k where eps_rho or eps_gradP vanish, the jumps, condition (22).
#include "cli/command.hpp"
#include "codes/code_table.hpp"
#include "requests/roots_request.hpp"
#include "support/error.hpp"

#include "stability/stability_scan.hpp"

#include <memory>

namespace sphkern::cli {

namespace {

struct RootsOptions : CommonOptions {
    std::string kernel, lattice;
    double k_min = 0, k_max = 0, epsilon = 0; // the defaults: requests/settings
    bool lateral = false;
    std::string axis;
    std::vector<std::string> sets;
    EvaluationOptions evaluation;
    bool stability = false;
    double gamma = 0, horizon = 0;
    int steps = 0, threads = 0;
    std::string convention, code;
    std::string h_model;
};

// The adapter: the option texts as types (an unknown axis, h model or code is refused here).
RootsRequest request_from(const RootsOptions& o)
{
    RootsRequest r;
    r.window_min = o.k_min;
    r.window_max = o.k_max;
    r.axis = parse_axis(o.axis, "--axis");
    r.epsilon = o.epsilon;
    r.lateral = o.lateral;
    r.stability = o.stability;
    r.model = {o.gamma, o.horizon, o.steps, parse_h_model(o.h_model, "--h-model"), o.threads};
    // --convention is the old name of --code: the same answer, with the code's own density.
    if (!o.convention.empty() && !o.code.empty())
        throw Error(ExitCode::usage, "give one of --code and --convention (its old name)");
    const std::string& code = o.code.empty() ? o.convention : o.code;
    if (!code.empty()) r.code = &code_profile(code, ValueSource::option(o.code.empty() ? "--convention" : "--code"));
    r.evaluation = evaluation_inputs(o.evaluation);
    return r;
}

// The command line's names for the request's values (the window refused as input, exit 3).
RootsSources option_sources(const RootsOptions& o)
{
    return {ValueSource::option("--kmin/--kmax"), ValueSource::option("--epsilon"), ValueSource::option("--gamma"),
            ValueSource::option("--horizon"),     ValueSource::option("--steps"),   evaluation_sources(o.evaluation),
            ValueSource::option("--threads")};
}

// The lattices and kernels named, "all" for every one.
std::vector<Lattice> lattices_of(const std::string& spec)
{
    std::vector<Lattice> lattices;
    if (spec == "all")
        for (const auto& name : shipped_lattice_names()) lattices.push_back(load_lattice(name));
    else lattices.push_back(load_lattice(spec));
    return lattices;
}

std::vector<Kernel> kernels_of(const RootsOptions& o, KernelRegistry& registry)
{
    std::vector<Kernel> kernels;
    if (o.kernel == "all")
        for (const auto& p : registry.plugins()) kernels.emplace_back(p, parse_sets(o.sets));
    else kernels.push_back(make_kernel(registry, o.kernel, o.sets));
    return kernels;
}

// The roots of every kernel and lattice named, as text or one JSON array.
int run_roots_command(const RootsOptions& o)
{
    const auto request = request_from(o);
    const auto sources = option_sources(o);
    check_roots_request(request, sources);
    auto registry = discover_kernels(o);
    const auto lattices = lattices_of(o.lattice);
    const auto kernels = kernels_of(o, registry);
    const bool many = kernels.size() > 1 || lattices.size() > 1;
    nlohmann::json all = nlohmann::json::array();
    for (const auto& lattice : lattices)
        for (const auto& kernel : kernels) {
            if (many && !kernel.supports(lattice.dimension)) continue; // "all": the pairs that exist
            const auto result = run_roots(request, sources, kernel, lattice);
            if (o.json) all.push_back(roots_request_document(request, result, kernel, lattice));
            else print_roots(request, result, kernel, lattice);
        }
    // One shape for one pair and for many: an array of documents.
    if (o.json) print_json(all);
    return 0;
}

} // namespace

Action add_roots_command(Command app)
{
    Command command = app.add_subcommand("roots", "Roots in k of eps_rho and eps_gradP, jumps and condition (22)");
    auto options = std::make_shared<RootsOptions>();
    command.add_setting("kernel", options->kernel);
    command.add_setting("lattice", options->lattice);
    command.add_setting("kmin", options->k_min);
    command.add_setting("kmax", options->k_max);
    command.add_setting("epsilon", options->epsilon);
    command.add_setting("lateral", options->lateral);
    command.add_setting("axis", options->axis);
    command.add_setting("stability", options->stability);
    command.add_setting("gamma", options->gamma);
    command.add_setting("steps", options->steps);
    command.add_setting("threads", options->threads);
    command.add_setting("convention", options->convention);
    command.add_setting("code", options->code);
    command.add_setting("horizon", options->horizon);
    command.add_setting("h_model", options->h_model);
    add_evaluation_options(command, options->evaluation);
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] { return run_roots_command(*options); };
}

} // namespace sphkern::cli
