// `sphkern spectrum`: the Fourier transform of a kernel against kappa h, with its
// minimum and first zero.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "kernels/kernel_spectrum.hpp"
#include "support/error.hpp"

#include <fmt/format.h>

#include <memory>

namespace sphkern::cli {

Action add_spectrum_command(CLI::App& app)
{
    auto* command = app.add_subcommand("spectrum", "Fourier transform of a kernel against kappa h");
    struct Options : CommonOptions {
        std::string kernel;
        int dim = 0;
        double k = 1, kh_max = spectrum_kh_max;
        int points = 500;
        std::vector<std::string> sets;
    };
    auto options = std::make_shared<Options>();
    command->add_option("kernel", options->kernel, "Kernel name or plugin file")->required();
    command->add_option("--dim", options->dim, "Dimension D (1, 2 or 3)")->required()->check(CLI::Range(1, 3));
    command->add_option("--k", options->k, "k for kernels whose formula depends on it")->capture_default_str()
        ->check(CLI::Range(1e-3, 100.0));
    command->add_option("--max", options->kh_max, "Largest kappa h")->capture_default_str()->check(CLI::Range(0.1, 1000.0));
    command->add_option("--points", options->points, "Intervals on [0, max]")->capture_default_str()
        ->check(CLI::Range(1, 100000));
    add_set_option(*command, options->sets);
    add_plugin_option(*command, *options);
    add_json_option(*command, *options);
    return [options] {
        auto registry = discover_kernels(*options);
        auto kernel = make_kernel(registry, options->kernel, options->sets);
        kernel.require_dimension(options->dim, fmt::format("(--dim {})", options->dim));
        const auto curve = spectrum_curve(kernel, options->dim, options->k, options->kh_max, options->points);
        const auto summary = spectrum_summary(kernel, options->dim, options->k);
        for (const auto& [kh, value] : curve)
            if (!std::isfinite(value))
                fail_input(fmt::format("kernel {}: its Fourier transform is not finite at kappa h = {}", kernel.label(), kh));
        if (options->json) {
            nlohmann::json points = nlohmann::json::array();
            for (const auto& [kh, value] : curve) points.push_back({kh, value});
            print_json({{"kernel", kernel.label()}, {"dimension", options->dim}, {"k", options->k},
                        {"source", summary.provided ? "plugin" : "quadrature"},
                        {"min", summary.minimum}, {"at", summary.at},
                        {"first_zero", summary.first_zero ? nlohmann::json(*summary.first_zero) : nlohmann::json()},
                        {"curve", points}},
                       command_inputs(&kernel, nullptr));
            return 0;
        }
        fmt::print(results_file(), "# Fourier transform of {} in {}D ({}): min {:.6g} at kappa h = {:.6g}, {}\n",
                   kernel.label(), options->dim, summary.provided ? "the plugin's" : "quadrature", summary.minimum,
                   summary.at,
                   summary.first_zero ? fmt::format("first zero at kappa h = {:.8g}", *summary.first_zero)
                                      : std::string("no zero on [0, 50]"));
        fmt::print(results_file(), "# kappa_h W_hat\n");
        for (const auto& [kh, value] : curve) fmt::print(results_file(), "{:.6f} {:.12g}\n", kh, value);
        return 0;
    };
}

} // namespace sphkern::cli
