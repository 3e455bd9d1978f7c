// `sphkern spectrum`: the Fourier transform of a kernel against kappa h, with its
// minimum and first zero.
#include "cli/command.hpp"
#include "requests/spectrum_request.hpp"

#include <memory>

namespace sphkern::cli {

Action add_spectrum_command(Command app)
{
    Command command = app.add_subcommand("spectrum", "Fourier transform of a kernel against kappa h");
    struct Options : CommonOptions {
        std::string kernel;
        SpectrumRequest request;
        std::vector<std::string> sets;
    };
    auto options = std::make_shared<Options>();
    auto& request = options->request;
    command.add_option("kernel", options->kernel, "Kernel name or plugin file").required();
    command.add_option("--dim", request.dimension, "Dimension D (1, 2 or 3)").required();
    command.add_option("--k", request.k, "k for kernels whose formula depends on it").capture_default_str();
    command.add_option("--max", request.kh_max, "Largest kappa h").capture_default_str();
    command.add_option("--points", request.points, "Intervals on [0, max]").capture_default_str();
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options] {
        const SpectrumSources sources{ValueSource::option("--dim"), ValueSource::option("--k"),
                                      ValueSource::option("--max"), ValueSource::option("--points")};
        check_spectrum_request(options->request, sources);
        auto registry = discover_kernels(*options);
        auto kernel = make_kernel(registry, options->kernel, options->sets);
        const auto result = run_spectrum(options->request, sources, kernel);
        if (options->json)
            print_json(spectrum_document(options->request, result, kernel), command_inputs(&kernel, nullptr));
        else print_spectrum(options->request, result, kernel);
        return 0;
    };
}

} // namespace sphkern::cli
