// `sphkern particles`: the consistency errors of a kernel on any particle set (a lattice
// block, a Poisson set or a file), per particle and as statistics.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "cli/source_options.hpp"

#include "codes/code_table.hpp"
#include "particles/particles_memory.hpp"
#include "requests/particles_report.hpp"
#include "requests/particles_request.hpp"
#include "requests/source_request.hpp"
#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/output_targets.hpp"
#include "support/io/results_output.hpp"
#include "support/io/vtk_format.hpp"

#include <fmt/format.h>

#include <array>
#include <filesystem>
#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

struct ParticlesOptions : CommonOptions, SourceOptions {
    std::string kernel, gravity, volume, csv, vtk;
    std::vector<std::string> sets;
    std::vector<double> h_over_l_range, nh_range, eta_range;
    double depth = 1, memory_limit = 0;
    std::optional<double> h_over_l, eta, nh, k, support_per_h, rho0;
    SettingOptions codes; // --code and the codes' parameters but --eta (SWIFT's, with --code swift)
    int steps = 10, threads = 0;
    std::size_t histogram = 0;
};

std::optional<std::array<double, 2>> range_of(const std::vector<double>& values)
{
    if (values.empty()) return std::nullopt;
    return std::array<double, 2>{values[0], values[1]};
}

ParticleArguments arguments_of(const ParticlesOptions& o, ParticleSources& sources)
{
    ParticleArguments a;
    if (const auto code = code_beside_own_eta(o.codes, o.eta)) {
        sources.code.value = code_sources(o.codes).second;
        name_code(a, code->code, code->value);
    }
    if (!o.eta_range.empty())
        throw Error(ExitCode::usage, "--eta-range is the old name of --h-over-l-range, sphkern's own h over the mean spacing");
    a.smoothing = {o.h_over_l, o.nh, o.k, o.support_per_h};
    a.eta_range = range_of(o.h_over_l_range), a.nh_range = range_of(o.nh_range);
    a.steps = o.steps;
    if (!o.volume.empty()) a.volume = o.volume;
    if (!o.gravity.empty()) a.gravity = parse_number_list(o.gravity, sources.gravity);
    a.depth = o.depth, a.rho0 = o.rho0, a.threads = o.threads;
    a.histogram = static_cast<long long>(o.histogram);
    a.per_particle_files = !o.csv.empty() || !o.vtk.empty(); // they write e1 and m1
    return a;
}

void add_options(Command c, ParticlesOptions& o)
{
    c.add_option("kernel", o.kernel, "Kernel name or plugin file").required();
    add_source_options(c, o);
    c.add_option("--h-over-l", o.h_over_l, "h over the mean spacing l = V^(1/D), sphkern's own (default 1.2 without a "
                                           "file h)");
    c.add_option("--eta", o.eta, "With --code swift: SWIFT's eta, h = eta (m / rho)^(1/D)");
    c.add_option("--nh", o.nh, "h from the neighbour number N_H = c_D (R h)^D n");
    c.add_option("--k", o.k, "Lattice: h = k d");
    c.add_option("--code", o.codes.code, "h as an SPH code sets it, from each particle's SPH density where the code solves for "
                                   "it: swift (--eta), phantom (--hfact), gadget2 or gadget4 (--nngb), pysph (--hdx), "
                                   "dualsphysics (--coefh); without its parameter, a file's h as the code stores it");
    add_code_parameters(c, o.codes);
    c.add_option("--support-per-h", o.support_per_h, "File h: the support radius over the stored h (GADGET 1, SWIFT gamma, PySPH R)");
    c.add_option("--h-over-l-range", o.h_over_l_range, "Sweep h / l over [A, B]").expected(2);
    c.add_option("--eta-range", o.eta_range, "The old name of --h-over-l-range (refused, naming it)").expected(2).hidden();
    c.add_option("--nh-range", o.nh_range, "Sweep N_H over [A, B]").expected(2);
    c.add_option("--steps", o.steps, "Sweep: steps between A and B").capture_default_str();
    // The radius gives a SPlisHSPlasH file's h, which a rule for h would leave unused.
    c.get_option("--particle-radius").excludes("--h-over-l").excludes("--nh").excludes("--k")
        .excludes("--h-over-l-range").excludes("--nh-range").excludes("--code");
    c.add_option("--volume", o.volume, "uniform (box / N), file (m / rho) or voronoi (default: file if m and rho, else uniform)");
    c.add_option("--gravity", o.gravity, "Direction of eps_gradp, x,y[,z] (default: the lattice's, else -y or -z)");
    c.add_option("--depth", o.depth, "Depth of the sum form's eps_gradp_sum, in units of h").capture_default_str();
    c.add_option("--rho0", o.rho0, "Reference density of eps_rho (default: the set's total mass over its volume)");
    c.add_option("--histogram", o.histogram, "Histogram bins of e0, eps_rho, eps_gradp and eps_gradp_sum");
    c.add_option("--threads", o.threads, "Threads (default: every core)");
    c.add_option("--memory-limit", o.memory_limit, "Memory budget in GiB (default: three quarters of the available memory)");
    c.add_option("--csv", o.csv, "Write one row per particle as CSV");
    c.add_option("--vtk", o.vtk, "Write the per-particle values for ParaView: F.vtk legacy VTK, F.vtu VTK XML");
    add_set_option(c, o.sets);
    add_plugin_option(c, o);
    add_json_option(c, o);
}

// A snapshot larger than the memory budget, measured slab by slab: the same statistics and
// CSV as in memory, the CSV streamed in file order as the slabs' results are merged.
int measure_in_slabs(const ParticlesOptions& o, const Kernel& kernel, const SnapshotRows& snapshot, ParticleSources& sources,
                     const std::vector<OutputTarget>& outputs, FileDigest* digest)
{
    const ParticleSet& set = snapshot.sample();
    check_output_targets(outputs, set.linked_files); // what the file reached through its links
    if (!o.vtk.empty())
        throw Error(ExitCode::input, fmt::format("--vtk {}: {} is measured in slabs (over the memory budget), whose "
                                                 "per-particle values are written as --csv only",
                                                 o.vtk, set.name));
    const auto arguments = arguments_of(o, sources);
    const ParticleRequest request = particle_request(arguments, kernel, set, sources);
    ParticleAnswer answer;
    if (o.csv.empty()) answer = analyse_particles_in_slabs(kernel, snapshot, request, {});
    else
        write_file_atomically(o.csv, [&](std::ostream& out) {
            ParticleCsvRows csv(out, set.dimension, worker_threads(o.threads));
            answer = analyse_particles_in_slabs(kernel, snapshot, request, [&](const MeasuredRows& rows) { csv.write(rows); });
        });
    if (o.json) print_json(particle_answer_json(kernel, set, answer, arguments), source_inputs(o, kernel, digest));
    else print_particle_answer(results_file(), kernel, set, answer, arguments);
    return 0;
}

} // namespace

Action add_particles_command(Command app)
{
    Command command = app.add_subcommand("particles", "Consistency errors of a kernel on any particle set");
    auto options = std::make_shared<ParticlesOptions>();
    add_options(command, *options);
    return [options, command] {
        const auto& o = *options;
        set_memory_budget(o.memory_limit, value_named(FrontEnd::command_line, "memory_limit"));
        const auto outputs = given_outputs(command, {{"--csv", o.csv}, {"--vtk", o.vtk}});
        check_output_targets(outputs, read_inputs(o.source, o.kernel, o.plugins));
        const auto vtk_format = o.vtk.empty() ? VtkFormat::legacy : vtk_format_of(o.vtk, "--vtk");
        auto registry = discover_kernels(o);
        auto kernel = make_kernel(registry, o.kernel, o.sets);
        PhaseTimes phases;
        auto sources = particle_sources(FrontEnd::command_line);
        check_threads(o.threads, sources.threads); // the set is read on them
        const auto digest = o.json ? start_source_digest(o) : nullptr;
        if (const auto snapshot = snapshot_in_slabs(source_of(o), source_sources(FrontEnd::command_line)))
            return measure_in_slabs(o, kernel, *snapshot, sources, outputs, digest.get());
        const ParticleSet set = load_source(source_of(o), source_sources(FrontEnd::command_line), o.threads);
        phases.lap("read");
        check_output_targets(outputs, set.linked_files); // what the file reached through its links
        const auto arguments = arguments_of(o, sources);
        ParticleAnswer answer = analyse_particles(kernel, set, particle_request(arguments, kernel, set, sources));
        phases.merge(answer.phases);
        phases.restart();
        if (!o.csv.empty()) write_file_atomically(o.csv, [&](std::ostream& out) { write_particle_csv(out, set, answer); });
        if (!o.vtk.empty())
            write_file_atomically(o.vtk, [&](std::ostream& out) {
                if (vtk_format == VtkFormat::xml) write_particle_vtu(out, set, answer);
                else write_particle_vtk(out, set, answer);
            });
        if (!outputs.empty()) phases.lap("write");
        answer.phases = phases;
        if (o.json) print_json(particle_answer_json(kernel, set, answer, arguments), source_inputs(o, kernel, digest.get()));
        else print_particle_answer(results_file(), kernel, set, answer, arguments);
        return 0;
    };
}

} // namespace sphkern::cli
