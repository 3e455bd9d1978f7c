// `sphkern check`: the kernel author's check-up, run in a child process.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "kernels/kernel_check.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <memory>

namespace sphkern::cli {

Action add_check_command(CLI::App& app)
{
    auto* command = app.add_subcommand("check", "Check kernels: normalisation, derivative, continuity, moments");
    struct Options : CommonOptions {
        std::vector<std::string> names;
        std::vector<std::string> sets;
        bool strict = false;
        bool all = false;
        double timeout = 60;
    };
    auto options = std::make_shared<Options>();
    command->add_option("kernel", options->names, "Kernel names (default with --plugin: that plugin)");
    add_plugin_option(*command, *options);
    add_json_option(*command, *options);
    add_set_option(*command, options->sets);
    command->add_flag("--all", options->all, "Check every kernel found");
    command->add_flag("--strict", options->strict, "Exit 1 on a warning too");
    command->add_option("--timeout", options->timeout, "Seconds a kernel may take")->capture_default_str()
        ->check(CLI::Range(0.1, 3600.0));
    return [options] {
        std::vector<std::filesystem::path> files(options->plugins.begin(), options->plugins.end());
        bool only_files = options->names.empty() && !options->all;
        if (only_files && files.empty())
            throw Error(ExitCode::usage, "check: name a kernel, give --plugin FILE, or use --all");
        auto registry = only_files ? KernelRegistry::from_files(files) : KernelRegistry::discover(files);
        std::vector<Kernel> kernels;
        if (options->all || only_files)
            for (const auto& p : registry.plugins()) kernels.emplace_back(p, parse_sets(options->sets));
        for (const auto& name : options->names) kernels.push_back(make_kernel(registry, name, options->sets));

        nlohmann::json results = nlohmann::json::array();
        bool failed = false;
        for (const auto& kernel : kernels) {
            auto result = check_kernel_isolated(kernel, options->timeout);
            std::string verdict = result["verdict"];
            failed |= verdict == "fail" || (options->strict && verdict == "warn");
            if (!options->json) {
                fmt::print(results_file(), "{} ({}): {}\n", kernel.label(), kernel.definition().source, verdict);
                for (const auto& c : result["checks"])
                    fmt::print(results_file(), "  {}D {:<14} {:<5} {}\n", c["dimension"].get<int>(), c["check"].get<std::string>(),
                               c["status"].get<std::string>(), c["detail"].get<std::string>());
                for (const auto& c : result["checks"])
                    if (c.contains("hint"))
                        fmt::print(results_file(), "  hint ({}D {}): {}\n", c["dimension"].get<int>(),
                                   c["check"].get<std::string>(), c["hint"].get<std::string>());
            }
            if (options->json) result["inputs"] = command_inputs(&kernel, nullptr);
            results.push_back(std::move(result));
        }
        if (options->json) print_json(results); // an array, for one kernel too
        return failed ? static_cast<int>(ExitCode::check_failed) : 0;
    };
}

} // namespace sphkern::cli
