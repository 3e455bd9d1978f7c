// `sphkern block`: direct SPH sums over a finite block of particles.
#include "cli/command.hpp"
#include "requests/block_request.hpp"

#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/output_targets.hpp"
#include "support/io/vtk_format.hpp"

#include <memory>
#include <sstream>

namespace sphkern::cli {

namespace {

struct BlockCommandOptions : CommonOptions {
    std::string kernel, lattice, size, form, vtk, csv; // the defaults: requests/settings
    double k = 0;
    bool periodic = false;
    int threads = 0;
    std::vector<std::string> sets;
    std::string ap;
};

// "N1,N2[,N3]": whole numbers (the request checks their count).
std::vector<long long> parse_size(const std::string& text)
{
    std::vector<long long> cells;
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        char* end = nullptr;
        long long v = std::strtoll(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0')
            throw Error(ExitCode::usage, "--size " + text + ": expected N1,N2[,N3] integers");
        cells.push_back(v);
    }
    return cells;
}

BlockRequest request_from(const BlockCommandOptions& o)
{
    BlockRequest r;
    r.k = o.k;
    r.cells = parse_size(o.size);
    r.periodic = o.periodic;
    r.form = parse_gradient_form(o.form);
    r.threads = o.threads;
    r.a_p = o.ap;
    return r;
}

void add_block_options(Command command, BlockCommandOptions& o)
{
    command.add_setting("kernel", o.kernel);
    command.add_setting("lattice", o.lattice);
    command.add_setting("k", o.k);
    command.add_setting("size", o.size);
    command.add_setting("periodic", o.periodic);
    command.add_setting("form", o.form);
    command.add_setting("threads", o.threads);
    command.add_setting("a_p", o.ap);
    command.add_setting("vtk", o.vtk);
    command.add_setting("csv", o.csv);
}

} // namespace

Action add_block_command(Command app)
{
    Command command = app.add_subcommand("block", "Direct SPH sums over a finite block of lattice cells");
    auto options = std::make_shared<BlockCommandOptions>();
    add_block_options(command, *options);
    add_set_option(command, options->sets);
    add_plugin_option(command, *options);
    add_json_option(command, *options);
    return [options, command] {
        check_output_targets(given_outputs(command, {{"--vtk", options->vtk}, {"--csv", options->csv}}),
                             read_inputs(options->lattice, options->kernel, options->plugins));
        const auto vtk_format = options->vtk.empty() ? VtkFormat::legacy : vtk_format_of(options->vtk, "--vtk");
        const auto request = request_from(*options);
        const BlockSources sources{ValueSource::option("--size " + options->size), ValueSource::option("--threads"),
                                   ValueSource::option("--k")};
        check_block_request(request, sources);
        const auto [lattice, kernel] = kernel_on_lattice(*options, options->kernel, options->lattice, options->sets);
        const auto run = run_block(request, sources, kernel, lattice);
        const auto& result = run.result;
        if (!options->vtk.empty())
            write_file_atomically(options->vtk, [&](std::ostream& o) {
                if (vtk_format == VtkFormat::xml) write_block_vtu(o, result);
                else write_block_vtk(o, result);
            });
        if (!options->csv.empty())
            write_file_atomically(options->csv, [&](std::ostream& o) { write_block_csv(o, result); });
        if (options->json) print_json(block_document(run, kernel, lattice), command_inputs(&kernel, &lattice));
        else print_block(run, kernel, lattice);
        return 0;
    };
}

} // namespace sphkern::cli
