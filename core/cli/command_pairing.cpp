// `sphkern pairing`: the linear stability verdict of a lattice beside the motion of its
// particles under the SPH pressure force, k by k.
#include "cli/code_options.hpp"
#include "cli/command.hpp"

#include "requests/pairing_request.hpp"
#include "requests/relax_report.hpp"
#include "support/error.hpp"
#include "support/io/results_output.hpp"

#include <memory>

namespace sphkern::cli {

namespace {

struct PairingOptions : CommonOptions {
    std::string kernel, lattice;
    std::vector<std::string> sets;
    SettingOptions setting;
    PairingRequest request;
};

void add_options(Command c, PairingOptions& o)
{
    c.add_option("kernel", o.kernel, "Kernel name or plugin file").required();
    c.add_option("lattice", o.lattice, "Lattice name or JSON file").required();
    auto& r = o.request;
    add_setting_options(c, o.setting, "One k (h = k d)");
    c.add_option("--kmin", r.k_min, "Smallest k of the range");
    c.add_option("--kmax", r.k_max, "Largest k of the range");
    c.add_option("--samples", r.samples, "Evenly spaced k over [kmin, kmax]").capture_default_str();
    c.add_option("--noise", r.noise, "Gaussian displacement per axis at the start, in units of d")
        .capture_default_str();
    c.add_option("--duration", r.duration, "Time of motion, in units of d / c").capture_default_str();
    c.add_option("--damping", r.damping, "Velocity damping rate, in units of c / h").capture_default_str();
    c.add_option("--dt", r.time_step, "Time step, in units of h / c").capture_default_str();
    c.add_option("--gamma", r.gamma, "Adiabatic index of P = rho0 c^2 / gamma (rho / rho0)^gamma")
        .capture_default_str();
    c.add_option("--horizon", r.horizon, "Growth time (d/c) beyond which the linear verdict is weak")
        .capture_default_str();
    c.add_option("--seed", r.seed, "Seed of the noise").capture_default_str();
    c.add_option("--threads", r.threads, "Threads (default: every core)");
    add_set_option(c, o.sets);
    add_plugin_option(c, o);
    add_json_option(c, o);
}

} // namespace

Action add_pairing_command(Command app)
{
    Command command =
        app.add_subcommand("pairing", "Linear stability against the motion of a disturbed lattice, k by k");
    auto options = std::make_shared<PairingOptions>();
    add_options(command, *options);
    return [options, command] {
        auto& o = *options;
        const bool range = command.count("--kmin") + command.count("--kmax") > 0;
        if (setting_given(o.setting) == range) throw Error(ExitCode::usage, "give --k, or --kmin and --kmax");
        std::optional<CodeSetting> code;
        if (!range) {
            code = code_setting(o.setting);
            // A code's k is known once the kernel and lattice are: checked then, as one k.
            o.request.k_min = o.request.k_max = code ? 1 : *o.setting.k, o.request.samples = 1;
        } else if (command.count("--kmin") != 1 || command.count("--kmax") != 1) {
            throw Error(ExitCode::usage, "a range needs both --kmin and --kmax");
        }
        const auto [code_source, value_source] = code_sources(o.setting);
        if (code) check_code_setting(*code, {code_source, value_source});
        check_pairing_request(o.request, pairing_sources(FrontEnd::command_line));
        const auto [lattice, kernel] = kernel_on_lattice(o, o.kernel, o.lattice, o.sets);
        const auto code_k = pairing_code_k(o.request, code, {code_source, value_source}, kernel, lattice);
        const auto points = pairing_motion(kernel, lattice, o.request);
        if (o.json)
            print_json(pairing_json(kernel, lattice, o.request, points, code_k), command_inputs(&kernel, &lattice));
        else print_pairing(results_file(), kernel, lattice, o.request, points, code_k);
        return 0;
    };
}

} // namespace sphkern::cli
