// `sphkern check`: the kernel author's check-up, run in a child process.
#include "cli/command.hpp"
#include "requests/check_request.hpp"

#include "support/error.hpp"

#include <memory>

namespace sphkern::cli {

namespace {

struct CheckOptions : CommonOptions {
    std::vector<std::string> names;
    std::vector<std::string> sets;
    bool strict = false;
    bool all = false;
    double timeout = 0; // the default: requests/settings
};

CheckRequest request_from(const CheckOptions& o)
{
    CheckRequest r;
    r.names = o.names;
    r.plugins.assign(o.plugins.begin(), o.plugins.end());
    r.all = o.all;
    r.strict = o.strict;
    r.timeout = o.timeout;
    return r;
}

} // namespace

Action add_check_command(Command app)
{
    Command command = app.add_subcommand("check", "Check kernels: normalisation, derivative, continuity, moments");
    auto options = std::make_shared<CheckOptions>();
    command.add_setting("kernel", options->names);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    add_set_option(command, options->sets);
    command.add_setting("all", options->all);
    command.add_setting("strict", options->strict);
    command.add_setting("timeout", options->timeout);
    return [options] {
        auto request = request_from(*options);
        check_check_request(request, check_sources(FrontEnd::command_line));
        request.parameters = parse_sets(options->sets); // after: naming nothing to check is said first
        auto registry = check_registry(request);
        const auto kernels = kernels_to_check(request, registry);
        nlohmann::json results = nlohmann::json::array();
        bool failed = false;
        for (const auto& kernel : kernels) {
            auto check = run_check(request, kernel);
            failed |= check_fails(check, request.strict);
            if (!options->json) print_check(check);
            if (options->json) check.document["inputs"] = command_inputs(&kernel, nullptr);
            results.push_back(std::move(check.document));
        }
        if (options->json) print_json(results); // an array, for one kernel too
        return failed ? static_cast<int>(ExitCode::check_failed) : 0;
    };
}

} // namespace sphkern::cli
