#include "requests/block_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "support/error.hpp"
#include "support/io/chunked_writer.hpp"
#include "support/io/results_output.hpp"
#include "support/io/vtk_points.hpp"
#include "support/io/vtk_xml.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <string>

namespace sphkern {

void check_block_request(const BlockRequest& r, const BlockSources& sources)
{
    check_k(r.k, sources.k);
    if (r.cells.size() > 3) sources.size.fail("expected N1,N2[,N3] integers");
    check_setting(settings_of("block")["threads"], r.threads, sources.threads);
}

BlockRun run_block(const BlockRequest& r, const BlockSources& sources, const Kernel& kernel, const Lattice& lattice)
{
    const auto dimension = static_cast<std::size_t>(lattice.dimension);
    if (r.cells.size() != dimension) // a value that does not fit the lattice: input, as for every source
        fail_input(
            fmt::format("{}: the lattice is {}D, expected {} cell counts", sources.size.name, dimension, dimension));
    BlockRun run;
    for (std::size_t a = 0; a < r.cells.size(); ++a) run.options.cells[a] = r.cells[a];
    run.options.periodic = r.periodic;
    run.options.k = r.k;
    run.options.a_p = volume_coefficient_of(lattice, r.a_p);
    run.options.form = r.form;
    run.options.threads = r.threads;
    run.result = evaluate_block(kernel, lattice, run.options);
    const double seconds = run.result.timings.evaluation;
    run.pairs_per_second = seconds > 0 ? static_cast<double>(run.result.pair_interactions) / seconds : 0;
    return run;
}

nlohmann::json block_document(const BlockRun& run, const Kernel& kernel, const Lattice& lattice)
{
    const auto& block = run.options;
    const auto& result = run.result;
    nlohmann::json layers = nlohmann::json::array();
    for (const auto& l : result.layers())
        layers.push_back({{"layer", l.layer},
                          {"particles", l.particles},
                          {"sites", l.sites},
                          {"eps_rho_min", l.rho_min},
                          {"eps_rho_max", l.rho_max},
                          {"eps_gradp_min", l.gradp_min},
                          {"eps_gradp_max", l.gradp_max}});
    return {{"kernel", kernel.label()},
            {"lattice", lattice.name},
            {"k", block.k},
            {"a_p", block.a_p},
            {"size", block.cells},
            {"periodic", block.periodic},
            {"form", gradient_form_name(block.form)},
            {"particles", result.particles()},
            {"pair_interactions_per_pass", result.pair_interactions},
            {"threads", result.threads},
            {"fused_passes", result.timings.fused},
            {"seconds", {{"setup", result.timings.setup}, {"evaluation", result.timings.evaluation}}},
            {"pair_interactions_per_second", run.pairs_per_second},
            {"layers", layers}};
}

void print_block(const BlockRun& run, const Kernel& kernel, const Lattice& lattice)
{
    const auto& result = run.result;
    fmt::print(results_file(), "{} on {}: {} particles, {} pair interactions per pass, {} threads\n", kernel.label(),
               lattice.name, result.particles(), result.pair_interactions, result.threads);
    fmt::print(results_file(), "setup {:.4f} s, density and gradient {:.4f} s ({}): {:.3g} pairs per second\n",
               result.timings.setup, result.timings.evaluation, result.timings.fused ? "one fused sweep" : "two passes",
               run.pairs_per_second);
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

// Per-particle values in the shortest form that reads back to the same double.
void write_block_vtk(std::ostream& out, const BlockResult& r)
{
    ChunkedWriter w(out);
    const std::size_t n = r.particles();
    write_vtk_points(w, "sphkern block: eps_rho and eps_gradp per particle", n, r.x.data(), r.y.data(), r.z.data(),
                     r.threads);
    auto scalars = [&](const char* header, const auto& values) {
        w.print("{}", header);
        w.rows(n, r.threads, [&](fmt::memory_buffer& row, std::size_t i) {
            fmt::format_to(std::back_inserter(row), "{}\n", values[i]);
        });
    };
    scalars("SCALARS eps_rho double 1\nLOOKUP_TABLE default\n", r.eps_rho);
    scalars("SCALARS eps_gradp double 1\nLOOKUP_TABLE default\n", r.eps_gradp);
    scalars("SCALARS layer int 1\nLOOKUP_TABLE default\n", r.layer);
}

void write_block_vtu(std::ostream& out, const BlockResult& r)
{
    const std::size_t n = r.particles();
    auto values = [](const auto& array) {
        return [&array](std::size_t i, int) { return static_cast<double>(array[i]); };
    };
    write_vtu(out, {{r.x.data(), n}, {r.y.data(), n}, {r.z.data(), n}},
              {{"layer", 1, values(r.layer)},
               {"eps_rho", 1, values(r.eps_rho)},
               {"eps_gradp", 1, values(r.eps_gradp)}});
}

void write_block_csv(std::ostream& out, const BlockResult& r)
{
    ChunkedWriter w(out);
    w.print("x,y,z,layer,eps_rho,eps_gradp\n");
    w.rows(r.particles(), r.threads, [&](fmt::memory_buffer& row, std::size_t i) {
        fmt::format_to(std::back_inserter(row), "{},{},{},{},{},{}\n", r.x[i], r.y[i], r.z[i], r.layer[i], r.eps_rho[i],
                       r.eps_gradp[i]);
    });
}

} // namespace sphkern
