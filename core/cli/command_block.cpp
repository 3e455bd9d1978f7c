// `sphkern block`: direct SPH sums over a finite block of particles.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "block/particle_block.hpp"
#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/chunked_writer.hpp"
#include "support/io/output_targets.hpp"
#include "support/io/vtk_points.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <memory>
#include <sstream>

namespace sphkern::cli {

namespace {

std::array<long long, 3> parse_size(const std::string& text, int dimension)
{
    std::array<long long, 3> cells = {1, 1, 1};
    std::stringstream list(text);
    std::string item;
    int n = 0;
    while (std::getline(list, item, ',')) {
        char* end = nullptr;
        long long v = std::strtoll(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || n >= 3)
            throw Error(ExitCode::usage, "--size " + text + ": expected N1,N2[,N3] integers");
        cells[static_cast<std::size_t>(n++)] = v;
    }
    if (n != dimension)
        throw Error(ExitCode::usage, "--size " + text + ": the lattice is " + std::to_string(dimension) + "D, give " +
                                         std::to_string(dimension) + " sizes");
    return cells;
}

void write_vtk(std::ostream& out, const BlockResult& r)
{
    ChunkedWriter w(out);
    const std::size_t n = r.particles();
    write_vtk_points(w, "sphkern block: eps_rho and eps_gradp per particle", n, r.x.data(), r.y.data(), r.z.data());
    w.print("SCALARS eps_rho double 1\nLOOKUP_TABLE default\n");
    for (double v : r.eps_rho) w.print("{:.17g}\n", v);
    w.print("SCALARS eps_gradp double 1\nLOOKUP_TABLE default\n");
    for (double v : r.eps_gradp) w.print("{:.17g}\n", v);
    w.print("SCALARS layer int 1\nLOOKUP_TABLE default\n");
    for (int v : r.layer) w.print("{}\n", v);
}

void write_csv(std::ostream& out, const BlockResult& r)
{
    ChunkedWriter w(out);
    w.print("x,y,z,layer,eps_rho,eps_gradp\n");
    for (std::size_t i = 0; i < r.particles(); ++i)
        w.print("{:.17g},{:.17g},{:.17g},{},{:.17g},{:.17g}\n", r.x[i], r.y[i], r.z[i], r.layer[i], r.eps_rho[i],
                r.eps_gradp[i]);
}

void print_block_json(const Kernel& kernel, const Lattice& lattice, const BlockOptions& block, const BlockResult& result,
                      double rate)
{
    nlohmann::json layers = nlohmann::json::array();
    for (const auto& l : result.layers())
        layers.push_back({{"layer", l.layer}, {"particles", l.particles}, {"sites", l.sites},
                          {"eps_rho_min", l.rho_min}, {"eps_rho_max", l.rho_max},
                          {"eps_gradp_min", l.gradp_min}, {"eps_gradp_max", l.gradp_max}});
    print_json({{"kernel", kernel.label()}, {"lattice", lattice.name}, {"k", block.k}, {"a_p", block.a_p},
                {"size", block.cells}, {"periodic", block.periodic},
                {"form", gradient_form_name(block.form)}, {"particles", result.particles()},
                {"pair_interactions_per_pass", result.pair_interactions}, {"threads", result.threads},
                {"fused_passes", result.timings.fused},
                {"seconds", {{"setup", result.timings.setup}, {"evaluation", result.timings.evaluation}}},
                {"pair_interactions_per_second", rate}, {"layers", layers}},
               command_inputs(&kernel, &lattice));
}

void print_block_text(const Kernel& kernel, const Lattice& lattice, const BlockResult& result, double rate)
{
    fmt::print(results_file(), "{} on {}: {} particles, {} pair interactions per pass, {} threads\n", kernel.label(),
               lattice.name, result.particles(), result.pair_interactions, result.threads);
    fmt::print(results_file(), "setup {:.4f} s, density and gradient {:.4f} s ({}): {:.3g} pairs per second\n",
               result.timings.setup, result.timings.evaluation, result.timings.fused ? "one fused sweep" : "two passes",
               rate);
    const bool several = result.sites > 1;
    fmt::print(results_file(), "{:>5} {:>9} {}{:>14} {:>14} {:>14} {:>14}\n", "layer", "particles",
               several ? fmt::format("{:>8} ", "sites") : "", "eps_rho min", "eps_rho max", "eps_gradP min",
               "eps_gradP max");
    for (const auto& l : result.layers()) {
        std::string sites;
        for (int s : l.sites) sites += fmt::format("{}{}", sites.empty() ? "" : ",", s);
        fmt::print(results_file(), "{:>5} {:>9} {}{:>14.8f} {:>14.8f} {:>14.8f} {:>14.8f}\n", l.layer, l.particles,
                   several ? fmt::format("{:>8} ", sites) : "", l.rho_min, l.rho_max, l.gradp_min, l.gradp_max);
    }
}

} // namespace

Action add_block_command(CLI::App& app)
{
    auto* command = app.add_subcommand("block", "Direct SPH sums over a finite block of lattice cells");
    struct Options : CommonOptions {
        std::string kernel, lattice, size, form = "sum", vtk, csv;
        double k = 0;
        bool periodic = false;
        int threads = 0;
        std::vector<std::string> sets;
        std::string ap = "voronoi";
    };
    auto options = std::make_shared<Options>();
    command->add_option("kernel", options->kernel, "Kernel name or plugin file")->required();
    command->add_option("lattice", options->lattice, "Lattice name or file")->required();
    command->add_option("--k", options->k, "Smoothing coefficient, h = k d")->required();
    command->add_option("--size", options->size, "Cells along the basis vectors: N1,N2[,N3] (the last is vertical)")
        ->required();
    command->add_flag("--periodic", options->periodic, "Periodic lateral sides (the top is always free)");
    command->add_option("--form", options->form, "Gradient form: sum, difference or monaghan")->capture_default_str();
    command->add_option("--threads", options->threads, "Threads (default: every core)")->check(CLI::Range(0, 1024));
    command->add_option("--ap", options->ap, "Volume coefficient: a name or a positive number")->capture_default_str();
    command->add_option("--vtk", options->vtk, "Write per-particle results as a legacy VTK file (ParaView)");
    command->add_option("--csv", options->csv, "Write per-particle results as CSV");
    add_set_option(*command, options->sets);
    add_plugin_option(*command, *options);
    add_json_option(*command, *options);
    return [options, command] {
        check_output_targets(given_outputs(*command, {{"--vtk", options->vtk}, {"--csv", options->csv}}),
                             read_inputs(options->lattice, options->kernel, options->plugins));
        auto lattice = load_lattice(options->lattice);
        BlockOptions block;
        block.cells = parse_size(options->size, lattice.dimension);
        block.periodic = options->periodic;
        block.k = options->k;
        block.a_p = lattice.volume_coefficient(options->ap);
        block.form = parse_gradient_form(options->form);
        block.threads = options->threads;
        auto registry = discover_kernels(*options);
        auto kernel = make_kernel(registry, options->kernel, options->sets);
        auto result = evaluate_block(kernel, lattice, block);
        if (!options->vtk.empty()) write_file_atomically(options->vtk, [&](std::ostream& o) { write_vtk(o, result); });
        if (!options->csv.empty()) write_file_atomically(options->csv, [&](std::ostream& o) { write_csv(o, result); });

        // A pair is counted once, though it feeds both sums (as BENCHMARKS.md counts it).
        const double seconds = result.timings.evaluation;
        const double rate = seconds > 0 ? static_cast<double>(result.pair_interactions) / seconds : 0;
        if (options->json) print_block_json(kernel, lattice, block, result, rate);
        else print_block_text(kernel, lattice, result, rate);
        return 0;
    };
}

} // namespace sphkern::cli
