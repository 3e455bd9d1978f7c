// sphkern: accuracy of SPH smoothing kernels on regular particle lattices.
#include "cli/command.hpp"
#include "cli/usage_hints.hpp"
#include "requests/settings/command_settings.hpp"
#include "support/error.hpp"
#include "support/io/provenance.hpp"
#include "support/io/results_output.hpp"
#include "support/process/interruption.hpp"
#include "support/process/stray_children.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <system_error>

using namespace sphkern;

namespace {

int fail(const std::string& message, ExitCode code)
{
    std::fflush(results_file());
    std::cerr << "sphkern: error: " << one_line(spelled_message(FrontEnd::command_line, message)) << std::endl;
    return static_cast<int>(code);
}

// Results are complete only if they reached their file: a full disk is an output error.
int finish(int status)
{
    if (std::fflush(results_file()) != 0 || std::ferror(results_file()))
        return fail("cannot write the results to standard output", ExitCode::output);
    return status;
}

using Commands = std::vector<std::pair<CLI::App*, cli::Action>>;

Commands add_commands(CLI::App& app)
{
    Commands commands;
    cli::Command program(app);
    auto add = [&](cli::Action (*add_command)(cli::Command)) {
        std::size_t before = app.get_subcommands({}).size();
        cli::Action action = add_command(program);
        commands.emplace_back(app.get_subcommands({})[before], std::move(action));
    };
    for (auto* add_command :
         {cli::add_run_command, cli::add_kernels_command, cli::add_check_command, cli::add_lattices_command,
          cli::add_shells_command, cli::add_eps_command, cli::add_assess_command, cli::add_roots_command,
          cli::add_surface_command, cli::add_block_command, cli::add_design_command, cli::add_stability_command,
          cli::add_spectrum_command, cli::add_particles_command, cli::add_relax_command, cli::add_pairing_command,
          cli::add_studies_command})
        add(add_command);
    // An empty value ('') is never a number, a name or a file: refused before CLI11 reads it as 0.
    const CLI::Validator non_empty(
        [](std::string& value) { return value.empty() ? std::string("an empty value") : std::string(); }, "",
        "non-empty");
    for (auto* command : app.get_subcommands({}))
        for (auto* option : command->get_options())
            if (option->get_type_size() != 0 && !option->get_positional()) option->check(non_empty);
    return commands;
}

// Runs the command that was parsed; every error becomes one line and its exit code.
int run_parsed(const Commands& commands)
{
    try {
        for (auto& [command, action] : commands)
            if (command->parsed()) {
                spdlog::debug("running {}", command->get_name()); // tests wait for this line before signalling
                return finish(action());
            }
    } catch (const Error& e) {
        return fail(e.what(), e.code());
    } catch (const std::bad_alloc&) {
        return fail("out of memory", ExitCode::input);
    } catch (const std::system_error& e) {
        // A write to the results that failed (fmt throws when a full disk refuses it).
        if (std::ferror(results_file())) return fail("cannot write the results to standard output", ExitCode::output);
        return fail(std::string("the system refused: ") + e.what(), ExitCode::input);
    } catch (const std::exception& e) {
        return fail(e.what(), ExitCode::input);
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    // Logs go to stderr; results to stdout or files.
    auto logger = spdlog::stderr_color_mt("sphkern");
    logger->set_pattern("sphkern: %^%l%$: %v");
    spdlog::set_default_logger(logger);
    spdlog::set_level(spdlog::level::info);

    CLI::App app{"sphkern " SPHKERN_VERSION ": accuracy of SPH smoothing kernels on regular particle lattices"};
    app.set_version_flag("--version", version_text());
    record_command_line(argc, argv);
    app.require_subcommand(1);
    std::string log_level = "info";
    app.add_option("--log-level", log_level, "trace, debug, info, warn, error or off")
        ->capture_default_str()
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));

    const Commands commands = add_commands(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(cli::usage_message(app, e, argc, argv), ExitCode::usage);
    }
    spdlog::set_level(spdlog::level::from_str(log_level));

    install_interrupt_handlers();
    adopt_orphans(); // a daemon a plugin forks comes back to sphkern, which ends it at exit
    // Past a file-size limit (ulimit -f) a write fails with EFBIG, an error that names the
    // file and removes what was staged, instead of a signal that kills without a word.
    std::signal(SIGXFSZ, SIG_IGN);
    separate_results_from_stdout();
    const int status = run_parsed(commands);
    end_stray_children();
    return status;
}
