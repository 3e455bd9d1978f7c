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
    command.add_setting("kernel", options->kernel);
    command.add_setting("dim", request.dimension);
    command.add_setting("k", request.k);
    command.add_setting("max", request.kh_max);
    command.add_setting("points", request.points);
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
