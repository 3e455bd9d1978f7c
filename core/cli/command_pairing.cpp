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
    std::optional<double> k_min, k_max;
    PairingRequest request;
};

void add_options(Command c, PairingOptions& o)
{
    c.add_setting("kernel", o.kernel);
    c.add_setting("lattice", o.lattice);
    auto& r = o.request;
    add_setting_options(c, o.setting);
    c.add_setting("kmin", o.k_min);
    c.add_setting("kmax", o.k_max);
    c.add_setting("samples", r.samples);
    c.add_setting("noise", r.noise);
    c.add_setting("duration", r.duration);
    c.add_setting("damping", r.damping);
    c.add_setting("dt", r.time_step);
    c.add_setting("gamma", r.gamma);
    c.add_setting("horizon", r.horizon);
    c.add_setting("seed", r.seed);
    c.add_setting("threads", r.threads);
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
    return [options] {
        auto& o = *options;
        const bool range = o.k_min || o.k_max;
        if (setting_given(o.setting) == range) throw Error(ExitCode::usage, "give --k, or --kmin and --kmax");
        std::optional<CodeSetting> code;
        if (!range) {
            code = code_setting(o.setting);
            // A code's k is known once the kernel and lattice are: checked then, as one k.
            o.request.k_min = o.request.k_max = code ? 1 : *o.setting.k, o.request.samples = 1;
        } else if (!o.k_min || !o.k_max) {
            throw Error(ExitCode::usage, "a range needs both --kmin and --kmax");
        } else {
            o.request.k_min = *o.k_min, o.request.k_max = *o.k_max;
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
