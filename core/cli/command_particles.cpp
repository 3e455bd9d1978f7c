// `sphkern particles`: the consistency errors of a kernel on any particle set (a lattice
// block, a Poisson set or a file), per particle and as statistics.
#include "cli/code_options.hpp"
#include "cli/command.hpp"
#include "cli/particles_command.hpp"

#include "codes/code_table.hpp"
#include "particles/particles_memory.hpp"
#include "requests/particles_report.hpp"
#include "requests/particles_request.hpp"
#include "requests/settings/command_settings.hpp"
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
    c.add_setting("kernel", o.kernel);
    add_source_options(c, o);
    c.add_setting("more", o.more);
    c.add_setting("keep_going", o.keep_going);
    c.add_setting("plot", o.plot);
    c.add_setting("h_over_l", o.h_over_l);
    c.add_setting("eta", o.eta);
    c.add_setting("nh", o.nh);
    c.add_setting("k", o.k);
    c.add_setting("code", o.codes.code);
    add_code_parameters(c, o.codes);
    c.add_setting("neighbours_by", o.neighbours_by);
    c.add_setting("bias_correction", o.bias_correction);
    c.add_setting("support_per_h", o.support_per_h);
    c.add_setting("h_over_l_range", o.h_over_l_range).expected(2);
    c.add_setting("eta_range", o.eta_range).expected(2);
    c.add_setting("nh_range", o.nh_range).expected(2);
    c.add_setting("steps", o.steps);
    // The radius gives a SPlisHSPlasH file's h, which a rule for h would leave unused.
    c.get_option("--particle-radius")
        .excludes("--h-over-l")
        .excludes("--nh")
        .excludes("--k")
        .excludes("--h-over-l-range")
        .excludes("--nh-range")
        .excludes("--code");
    c.add_setting("volume", o.volume);
    c.add_setting("gravity", o.gravity);
    c.add_setting("depth", o.depth);
    c.add_setting("rho0", o.rho0);
    c.add_setting("histogram", o.histogram);
    c.add_setting("threads", o.threads);
    c.add_setting("memory_limit", o.memory_limit);
    c.add_setting("csv", o.csv);
    c.add_setting("vtk", o.vtk);
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
    check_setting(settings_of("particles")["threads"], o.threads, sources.threads); // the set is read on them
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
