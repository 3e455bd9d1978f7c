// `sphkern particles`: the consistency errors of a kernel on any particle set (a lattice
// block, a Poisson set or a file), per particle and as statistics.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "cli/particles_command.hpp"

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
    set_density_solve(a.code ? &*a.code : nullptr, o.neighbours_by, o.bias_correction);
    if (!o.eta_range.empty())
        throw Error(ExitCode::usage,
                    "--eta-range is the old name of --h-over-l-range, sphkern's own h over the mean spacing");
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
    c.add_option("more", o.more,
                 "Further snapshots of the run: the files (or folders) are measured as a series, ordered by "
                 "the times in their headers");
    c.add_flag("--keep-going", o.keep_going, "Series: report a snapshot that fails and go on with the rest");
    c.add_option("--plot", o.plot, "Series: draw the errors against time (median, p1 to p99) as .svg, .png or .pdf");
    c.add_option("--h-over-l", o.h_over_l,
                 "h over the mean spacing l = V^(1/D), sphkern's own (default 1.2 without a "
                 "file h)");
    c.add_option("--eta", o.eta, "With --code swift: SWIFT's eta, h = eta (m / rho)^(1/D)");
    c.add_option("--nh", o.nh, "h from the neighbour number N_H = c_D (R h)^D n");
    c.add_option("--k", o.k, "Lattice: h = k d");
    c.add_option("--code", o.codes.code,
                 "h as an SPH code sets it, from each particle's SPH density where the code solves for "
                 "it: swift (--eta), phantom (--hfact), gadget2 or gadget4 (--nngb), pysph (--hdx), "
                 "dualsphysics (--coefh); without its parameter, a file's h as the code stores it");
    add_code_parameters(c, o.codes);
    c.add_option("--neighbours-by", o.neighbours_by,
                 "With --code: what its density solve counts, number or mass (default the "
                 "code's; SWIFT's use_mass_weighted_num_ngb is mass)");
    c.add_flag("--bias-correction", o.bias_correction,
               "With --code: the density bias the code subtracts when built so "
               "(gadget4: WENDLAND_BIAS_CORRECTION, Wendland kernels in 3D)");
    c.add_option("--support-per-h", o.support_per_h,
                 "File h: the support radius over the stored h (GADGET 1, SWIFT gamma, PySPH R)");
    c.add_option("--h-over-l-range", o.h_over_l_range, "Sweep h / l over [A, B]").expected(2);
    c.add_option("--eta-range", o.eta_range, "The old name of --h-over-l-range (refused, naming it)")
        .expected(2)
        .hidden();
    c.add_option("--nh-range", o.nh_range, "Sweep N_H over [A, B]").expected(2);
    c.add_option("--steps", o.steps, "Sweep: steps between A and B").capture_default_str();
    // The radius gives a SPlisHSPlasH file's h, which a rule for h would leave unused.
    c.get_option("--particle-radius")
        .excludes("--h-over-l")
        .excludes("--nh")
        .excludes("--k")
        .excludes("--h-over-l-range")
        .excludes("--nh-range")
        .excludes("--code");
    c.add_option("--volume", o.volume,
                 "uniform (box / N), file (m / rho) or voronoi (default: file if m and rho, else uniform)");
    c.add_option("--gravity", o.gravity, "Direction of eps_gradp, x,y[,z] (default: the lattice's, else -y or -z)");
    c.add_option("--depth", o.depth, "Depth of the sum form's eps_gradp_sum, in units of h").capture_default_str();
    c.add_option("--rho0", o.rho0, "Reference density of eps_rho (default: the set's total mass over its volume)");
    c.add_option("--histogram", o.histogram, "Histogram bins of e0, eps_rho, eps_gradp and eps_gradp_sum");
    c.add_option("--threads", o.threads, "Threads (default: every core)");
    c.add_option("--memory-limit", o.memory_limit,
                 "Memory budget in GiB (default: three quarters of the available memory)");
    c.add_option("--csv", o.csv, "Write one row per particle as CSV");
    c.add_option("--vtk", o.vtk, "Write the per-particle values for ParaView: F.vtk legacy VTK, F.vtu VTK XML");
    add_set_option(c, o.sets);
    add_plugin_option(c, o);
    add_json_option(c, o);
}

// A snapshot larger than the memory budget, measured slab by slab: the same statistics and
// CSV as in memory, the CSV streamed in file order as the slabs' results are merged.
Measured measure_in_slabs(const ParticlesOptions& o, const Kernel& kernel, const SnapshotRows& snapshot,
                          ParticleSources& sources, const std::string& csv, const std::string& vtk,
                          const SetCheck& check)
{
    Measured m{snapshot.sample(), {}, arguments_of(o, sources)};
    if (check) check(m.set);
    if (!vtk.empty())
        throw Error(ExitCode::input, fmt::format("--vtk {}: {} is measured in slabs (over the memory budget), whose "
                                                 "per-particle values are written as --csv only",
                                                 vtk, m.set.name));
    const ParticleRequest request = particle_request(m.arguments, kernel, m.set, sources);
    if (csv.empty()) m.answer = analyse_particles_in_slabs(kernel, snapshot, request, {});
    else
        write_file_atomically(csv, [&](std::ostream& out) {
            ParticleCsvRows rows(out, m.set.dimension, worker_threads(o.threads));
            m.answer =
                analyse_particles_in_slabs(kernel, snapshot, request, [&](const MeasuredRows& r) { rows.write(r); });
        });
    return m;
}

} // namespace

// One source measured, in memory or in slabs, its per-particle values written to `csv` and `vtk`
// (either may be empty).
Measured measure_source(const ParticlesOptions& o, const Kernel& kernel, const std::vector<OutputTarget>& outputs,
                        const std::string& csv, const std::string& vtk, const SetCheck& check)
{
    PhaseTimes phases;
    auto sources = particle_sources(FrontEnd::command_line);
    check_threads(o.threads, sources.threads); // the set is read on them
    if (const auto snapshot = snapshot_in_slabs(source_of(o), source_sources(FrontEnd::command_line))) {
        check_output_targets(outputs, snapshot->sample().linked_files); // what the file reached through its links
        return measure_in_slabs(o, kernel, *snapshot, sources, csv, vtk, check);
    }
    Measured m{load_source(source_of(o), source_sources(FrontEnd::command_line), o.threads),
               {},
               arguments_of(o, sources)};
    phases.lap("read");
    check_output_targets(outputs, m.set.linked_files); // what the file reached through its links
    if (!vtk.empty()) vtk_format_of(vtk, "--vtk");     // before any work
    if (check) check(m.set);
    m.answer = analyse_particles(kernel, m.set, particle_request(m.arguments, kernel, m.set, sources));
    phases.merge(m.answer.phases);
    phases.restart();
    if (!csv.empty()) write_file_atomically(csv, [&](std::ostream& out) { write_particle_csv(out, m.set, m.answer); });
    if (!vtk.empty())
        write_file_atomically(vtk, [&](std::ostream& out) {
            if (vtk_format_of(vtk, "--vtk") == VtkFormat::xml) write_particle_vtu(out, m.set, m.answer);
            else write_particle_vtk(out, m.set, m.answer);
        });
    if (!csv.empty() || !vtk.empty()) phases.lap("write");
    m.answer.phases = phases;
    return m;
}

namespace {} // namespace

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
        auto registry = discover_kernels(o);
        auto kernel = make_kernel(registry, o.kernel, o.sets);
        if (!o.more.empty() || std::filesystem::is_directory(o.source)) return measure_series(o, kernel);
        if (!o.plot.empty())
            throw Error(ExitCode::usage,
                        "--plot " + o.plot + ": draws a series' errors against time; expected several snapshots");
        const auto digest = o.json ? start_source_digest(o) : nullptr;
        const Measured m = measure_source(o, kernel, outputs, o.csv, o.vtk);
        if (o.json)
            print_json(particle_answer_json(kernel, m.set, m.answer, m.arguments),
                       source_inputs(o, kernel, digest.get()));
        else print_particle_answer(results_file(), kernel, m.set, m.answer, m.arguments);
        return 0;
    };
}

} // namespace sphkern::cli
