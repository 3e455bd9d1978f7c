// `sphkern particles`: the consistency errors of a kernel on any particle set (a lattice
// block, a Poisson set or a file), per particle and as statistics.
#include "cli/command.hpp"

#include "particles/particle_report.hpp"
#include "particles/particles_memory.hpp"
#include "particles/sources/particle_source.hpp"
#include "support/atomic_file.hpp"
#include "support/output_targets.hpp"
#include "support/error.hpp"
#include "support/results_output.hpp"
#include "support/sha256.hpp"

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>

namespace sphkern::cli {

namespace {

struct ParticlesOptions : CommonOptions {
    std::string kernel, source, size, box, gravity, volume, array, csv, vtk;
    std::vector<std::string> sets;
    std::vector<double> eta_range, nh_range;
    double sigma = 0, depth = 1, memory_limit = 0;
    std::optional<double> eta, nh, k, support_per_h, rho0;
    unsigned long long seed = 1, count = 0;
    int dim = 0, steps = 10, threads = 0;
    std::size_t histogram = 0;
};

ParticleSource source_of(const ParticlesOptions& o)
{
    ParticleSource source;
    source.spec = o.source;
    source.kind = source_kind(o.source);
    if (source.kind != SourceKind::lattice && !o.size.empty())
        throw Error(ExitCode::usage, "--size cuts a lattice into a block; " + o.source + " is not a lattice");
    if (source.kind != SourceKind::poisson && o.count)
        throw Error(ExitCode::usage, "--count is for poisson sets");
    if (source.kind == SourceKind::lattice) {
        if (o.size.empty()) throw Error(ExitCode::usage, "a lattice source needs --size N1,N2[,N3] (cells of the periodic block)");
        const auto cells = parse_number_list("--size", o.size, 2, 3);
        for (std::size_t a = 0; a < cells.size(); ++a) {
            if (cells[a] != std::floor(cells[a]) || cells[a] < 1 || cells[a] > 1e6)
                throw Error(ExitCode::usage, "--size " + o.size + ": expected positive whole numbers of cells");
            source.block.cells[a] = static_cast<long long>(cells[a]);
        }
        if (cells.size() == 2) source.block.cells[2] = 1;
        source.block.sigma = o.sigma;
        source.block.seed = o.seed;
        const int dim = load_lattice(o.source).dimension;
        if (static_cast<int>(cells.size()) != dim)
            throw Error(ExitCode::usage, "--size " + o.size + ": the lattice is " + std::to_string(dim) + "D, give " +
                                             std::to_string(dim) + " sizes");
    } else if (o.sigma != 0) {
        throw Error(ExitCode::usage, "--sigma disturbs a lattice; " + o.source + " is not a lattice");
    }
    if (source.kind == SourceKind::poisson) {
        if (!o.count) throw Error(ExitCode::usage, "a poisson set needs --count N");
        source.poisson.count = o.count;
        source.poisson.dimension = o.dim ? o.dim : 3;
        source.poisson.seed = o.seed;
        if (!o.box.empty()) {
            const auto sides = parse_number_list("--box", o.box, 1, 3);
            for (int a = 0; a < 3; ++a)
                source.poisson.box[a] = sides[sides.size() == 1 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(a), sides.size() - 1)];
            if (sides.size() != 1 && static_cast<int>(sides.size()) != source.poisson.dimension)
                throw Error(ExitCode::usage, "--box " + o.box + ": give one side or one per dimension");
        }
    }
    if (source.kind == SourceKind::file) {
        source.file.array = o.array;
        if (o.dim) source.file.dimension = o.dim;
        if (!o.box.empty()) {
            const auto sides = parse_number_list("--box", o.box, 2, 3);
            source.box = Eigen::Vector3d(sides[0], sides[1], sides.size() == 3 ? sides[2] : 1.0);
        }
    } else if (!o.array.empty()) {
        throw Error(ExitCode::usage, "--array chooses a PySPH particle array; " + o.source + " is not a file");
    }
    return source;
}

ParticleRequest request_of(const ParticlesOptions& o, const ParticleSet& set)
{
    ParticleRequest request;
    const int rules = o.eta.has_value() + o.nh.has_value() + o.k.has_value() + !o.eta_range.empty() + !o.nh_range.empty();
    if (rules > 1) throw Error(ExitCode::usage, "give one of --eta, --nh, --k, --eta-range and --nh-range");
    if (o.eta) request.smoothing = {SmoothingRule::eta, *o.eta, 0};
    else if (o.nh) request.smoothing = {SmoothingRule::nh, *o.nh, 0};
    else if (o.k) request.smoothing = {SmoothingRule::k, *o.k, 0};
    else if (!set.h.empty() && o.eta_range.empty() && o.nh_range.empty())
        request.smoothing = {SmoothingRule::file, 0, o.support_per_h.value_or(0)};
    else request.smoothing = {SmoothingRule::eta, 1.2, 0}; // the documented default
    if (o.support_per_h && (request.smoothing.rule != SmoothingRule::file || *o.support_per_h <= 0))
        throw Error(ExitCode::usage, "--support-per-h maps a file's h (a positive number); it does not go with --eta, --nh or --k");
    if (!o.eta_range.empty() || !o.nh_range.empty()) {
        const bool eta = !o.eta_range.empty();
        const auto& range = eta ? o.eta_range : o.nh_range;
        request.sweep = SmoothingSweep{eta ? SmoothingRule::eta : SmoothingRule::nh, range[0], range[1], o.steps};
        if (!o.csv.empty() || !o.vtk.empty())
            throw Error(ExitCode::usage, "--csv and --vtk write one h per particle; they do not go with a sweep");
    }
    if (!o.volume.empty()) request.volume = parse_volume_model(o.volume);
    if (!o.gravity.empty()) request.gravity = parse_direction(o.gravity, set.dimension, "--gravity");
    request.depth = o.depth;
    request.rho0 = o.rho0;
    request.threads = o.threads;
    request.histogram_bins = o.histogram;
    return request;
}

void add_options(CLI::App& c, ParticlesOptions& o)
{
    c.add_option("kernel", o.kernel, "Kernel name or plugin file")->required();
    c.add_option("source", o.source, "A lattice (name or file), poisson, or a particle file (.h5/.hdf5, .csv, .vtk)")
        ->required();
    c.add_option("--size", o.size, "Lattice: cells of the periodic block, N1,N2[,N3]");
    c.add_option("--sigma", o.sigma, "Lattice: Gaussian displacement per axis, in units of d");
    c.add_option("--seed", o.seed, "Lattice and poisson: the random seed")->capture_default_str();
    c.add_option("--count", o.count, "Poisson: number of particles");
    c.add_option("--dim", o.dim, "Poisson: 2 or 3 (default 3); file: 2 reads a 3-column set with one constant coordinate")
        ->check(CLI::IsMember({2, 3}));
    c.add_option("--box", o.box, "Poisson: the box sides (default 1); file: a periodic box Lx,Ly[,Lz] from the origin");
    c.add_option("--array", o.array, "PySPH file: the particle array");
    c.add_option("--eta", o.eta, "h = eta times the mean spacing V^(1/D) (default 1.2 without a file h)");
    c.add_option("--nh", o.nh, "h from the neighbour number N_H = c_D (R h)^D n");
    c.add_option("--k", o.k, "Lattice: h = k d");
    c.add_option("--support-per-h", o.support_per_h, "File h: the support radius over the stored h (GADGET 1, SWIFT gamma, PySPH R)");
    c.add_option("--eta-range", o.eta_range, "Sweep eta over [A, B]")->expected(2);
    c.add_option("--nh-range", o.nh_range, "Sweep N_H over [A, B]")->expected(2);
    c.add_option("--steps", o.steps, "Sweep: steps between A and B")->capture_default_str();
    c.add_option("--volume", o.volume, "uniform (box / N), file (m / rho) or voronoi (default: file if m and rho, else uniform)");
    c.add_option("--gravity", o.gravity, "Direction of eps_gradp, x,y[,z] (default: the lattice's, else -y or -z)");
    c.add_option("--depth", o.depth, "Depth of the sum form's eps_gradp_sum, in units of h")->capture_default_str();
    c.add_option("--rho0", o.rho0, "Reference density of eps_rho (default: the set's total mass over its volume)");
    c.add_option("--histogram", o.histogram, "Histogram bins of e0, eps_rho and eps_gradp");
    c.add_option("--threads", o.threads, "Threads (default: every core)")->check(CLI::Range(0, 1024));
    c.add_option("--memory-limit", o.memory_limit, "Memory budget in GiB (default: three quarters of the available memory)");
    c.add_option("--csv", o.csv, "Write one row per particle as CSV");
    c.add_option("--vtk", o.vtk, "Write the per-particle values as a legacy VTK file (ParaView)");
    add_set_option(c, o.sets);
    add_plugin_option(c, o);
    add_json_option(c, o);
}

// The kernel, the lattice and the source as given, and a file's SHA-256: enough to run it again.
nlohmann::json particle_inputs(const ParticlesOptions& o, const Kernel& kernel)
{
    const auto kind = source_kind(o.source);
    std::optional<Lattice> lattice;
    if (kind == SourceKind::lattice) lattice = load_lattice(o.source);
    nlohmann::json inputs = command_inputs(&kernel, lattice ? &*lattice : nullptr);
    nlohmann::json source = {{"spec", o.source}, {"size", o.size}, {"sigma", o.sigma}, {"seed", o.seed},
                             {"count", o.count}, {"box", o.box}, {"array", o.array}};
    if (kind == SourceKind::file) source["sha256"] = file_sha256_hex(o.source);
    inputs["particles"] = source;
    return inputs;
}

} // namespace

Action add_particles_command(CLI::App& app)
{
    auto* command = app.add_subcommand("particles", "Consistency errors of a kernel on any particle set");
    auto options = std::make_shared<ParticlesOptions>();
    add_options(*command, *options);
    return [options, command] {
        const auto& o = *options;
        set_memory_limit_gib(o.memory_limit);
        check_output_targets(given_outputs(*command, {{"--csv", o.csv}, {"--vtk", o.vtk}}),
                             read_inputs(o.source, o.kernel, o.plugins));
        auto registry = discover_kernels(o);
        auto kernel = make_kernel(registry, o.kernel, o.sets);
        const ParticleSet set = load_particles(source_of(o));
        const ParticleAnswer answer = analyse_particles(kernel, set, request_of(o, set));
        if (!o.csv.empty()) write_file_atomically(o.csv, [&](std::ostream& out) { write_particle_csv(out, set, answer); });
        if (!o.vtk.empty()) write_file_atomically(o.vtk, [&](std::ostream& out) { write_particle_vtk(out, set, answer); });
        if (o.json) print_json(particle_answer_json(kernel, set, answer), particle_inputs(o, kernel));
        else print_particle_answer(results_file(), kernel, set, answer);
        return 0;
    };
}

} // namespace sphkern::cli
