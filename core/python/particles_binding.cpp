// sphkern.particles: the particle-set measures on numpy arrays. Positions are copied once
// (into the engine's own layout); the per-particle results come back as numpy arrays.
#include "particles_binding.hpp"
#include "docstrings.hpp"
#include "module_support.hpp"
#include "python_arrays.hpp"
#include "python_types.hpp"
#include "setting_keywords.hpp"

#include "codes/code_table.hpp"
#include "particles/particle_set.hpp"
#include "requests/assess_particles.hpp"
#include "requests/assess_sweep.hpp"
#include "requests/particles_report.hpp"
#include "requests/particles_request.hpp"
#include "requests/particles_series.hpp"
#include "requests/settings/command_settings.hpp"
#include "study/series_figure.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace py = pybind11;

namespace sphkern {

namespace {

ParticleValues per_particle(const py::object& value, std::size_t n, const char* what)
{
    const DoubleArray a = real_array(value, what, fmt::format("a number or an array of {} numbers", n));
    if (a.ndim() == 0 || (a.ndim() == 1 && a.size() == 1)) return ParticleValues(n, *a.data());
    if (a.ndim() != 1 || static_cast<std::size_t>(a.size()) != n)
        fail_input(fmt::format("{}: expected a number or an array of {} numbers", what, n));
    return ParticleValues(a.data(), a.data() + n);
}

ParticleSet set_of(const py::object& positions, const py::object& box)
{
    const DoubleArray p = real_array(positions, "positions", "an array of shape (N, 2) or (N, 3)");
    if (p.ndim() != 2 || (p.shape(1) != 2 && p.shape(1) != 3))
        fail_input("positions: expected an array of shape (N, 2) or (N, 3)");
    ParticleSet set;
    set.name = "positions";
    set.dimension = static_cast<int>(p.shape(1));
    const std::size_t n = static_cast<std::size_t>(p.shape(0)), dim = static_cast<std::size_t>(set.dimension);
    set.x.resize(n), set.y.resize(n), set.z.assign(n, 0.0);
    const double* data = p.data();
    for (std::size_t i = 0; i < n; ++i) {
        set.x[i] = data[i * dim], set.y[i] = data[i * dim + 1];
        if (dim == 3) set.z[i] = data[i * dim + 2];
    }
    if (dim == 2) set.gravity = Eigen::Vector3d(0, -1, 0);
    if (!box.is_none()) {
        const auto sides = per_particle(box, dim, "box");
        PeriodicBox b;
        for (std::size_t a = 0; a < dim; ++a) {
            if (!std::isfinite(sides[a]) || sides[a] <= 0) fail_input("box: expected positive sides");
            b.edges(static_cast<int>(a), static_cast<int>(a)) = sides[a];
        }
        set.box = b;
    }
    return set;
}

// Masses and densities, one positive finite number per particle, refused naming the argument.
ParticleValues positive_per_particle(const py::object& value, std::size_t n, const char* what, const char* field)
{
    auto values = per_particle(value, n, what);
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(values[i]) || values[i] <= 0)
            fail_input(fmt::format("{}: the {} of particle {} is {}, expected a positive finite number", what, field, i,
                                   values[i]));
    return values;
}

std::optional<double> number_of(const py::object& value, const char* what)
{
    if (value.is_none()) return std::nullopt;
    const DoubleArray a = real_array(value, what, "a number");
    if (a.size() != 1) fail_input(fmt::format("{}: expected a number", what));
    return *a.data();
}

// What the arguments give per particle goes into the set, as a file's columns would: h as
// stored (the support radius is support_per_h times it; sphkern's own h by default), masses
// and densities (the volumes m / rho where no volume is given).
struct GivenPerParticle {
    py::object h, support_per_h, masses, densities;
};

// The arguments as the request takes them.
ParticleArguments arguments_of(ParticleSet& set, const Kernel& kernel, const GivenPerParticle& given,
                               const py::object& h_over_l, const py::object& nh, const py::object& volume,
                               const py::object& gravity)
{
    if (!given.h.is_none() + !h_over_l.is_none() + !nh.is_none() > 1) fail_input("give one of h, h_over_l and nh");
    if (!given.densities.is_none() && given.masses.is_none())
        fail_input("densities: they give the volumes m / rho; expected masses too");
    if (!given.densities.is_none() && !volume.is_none()) fail_input("give one of volume and densities");
    ParticleArguments a;
    if (!given.h.is_none()) set.h = per_particle(given.h, set.size(), "h");
    // Given alone, the request refuses it (it maps a given h).
    a.smoothing.support_per_h = number_of(given.support_per_h, "support_per_h");
    if (!given.h.is_none() && !a.smoothing.support_per_h) a.smoothing.support_per_h = kernel.support();
    if (!given.masses.is_none()) set.mass = positive_per_particle(given.masses, set.size(), "masses", "mass");
    if (!given.densities.is_none())
        set.density = positive_per_particle(given.densities, set.size(), "densities", "density");
    a.smoothing.eta = number_of(h_over_l, "h_over_l"), a.smoothing.nh = number_of(nh, "nh");
    if (py::isinstance<py::str>(volume)) {
        const auto name = volume.cast<std::string>();
        if (name != "uniform" && name != "voronoi")
            fail_unknown("volume: \"" + one_line(name) +
                         "\" is unknown, expected \"uniform\", \"voronoi\" or an array");
        a.volume = name;
    } else if (!volume.is_none()) {
        const auto volumes = per_particle(volume, set.size(), "volume");
        a.volumes.assign(volumes.begin(), volumes.end());
    }
    if (!gravity.is_none()) {
        const DoubleArray g = real_array(gravity, "gravity", "a sequence of numbers");
        a.gravity = std::vector<double>(g.data(), g.data() + g.size());
    }
    a.per_particle_files = true; // the arrays returned
    return a;
}

py::array_t<double> column(const PerParticle& values)
{
    py::array_t<double> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out.mutable_at(i) = values[i];
    return out;
}

template <std::size_t N>
py::array_t<double> rows(std::span<const std::array<double, N>> values, std::size_t width)
{
    py::array_t<double> out({values.size(), width});
    auto view = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < values.size(); ++i)
        for (std::size_t a = 0; a < width; ++a) view(i, a) = values[i][a];
    return out;
}

py::array_t<double> tensors(std::span<const std::array<double, 6>> E, int dim)
{
    const std::size_t d = static_cast<std::size_t>(dim);
    py::array_t<double> out({E.size(), d, d});
    auto view = out.mutable_unchecked<3>();
    const int index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
    for (std::size_t i = 0; i < E.size(); ++i)
        for (std::size_t a = 0; a < d; ++a)
            for (std::size_t b = 0; b < d; ++b) view(i, a, b) = E[i][static_cast<std::size_t>(index[a][b])];
    return out;
}

// neighbours_by and bias_correction: what the code's density solve counts and the bias it
// subtracts, given with code and value (the command line's --neighbours-by, --bias-correction).
void set_density_solve(ParticleArguments& arguments, const std::optional<std::string>& neighbours_by,
                       bool bias_correction)
{
    if (neighbours_by) {
        if (!arguments.code)
            fail_input("neighbours_by: what a code's density solve counts; expected code and value too");
        if (*neighbours_by != "number" && *neighbours_by != "mass")
            fail_input(fmt::format("neighbours_by: \"{}\", expected \"number\" or \"mass\"", *neighbours_by));
        arguments.code->counts = *neighbours_by == "number" ? NeighbourCount::number : NeighbourCount::mass;
    }
    if (bias_correction) {
        if (!arguments.code)
            fail_input("bias_correction: the code's correction of its density solve; expected code and value too");
        arguments.code->bias_correction = true;
    }
}

// The keywords of one measure, as given.
struct Given {
    py::object h, support_per_h, h_over_l, nh;
    std::optional<std::string> code;
    py::object value;
    std::optional<std::string> neighbours_by;
    bool bias_correction;
    py::object masses, densities, rho0, volume, gravity;
    double depth;
    int threads;
    py::object h_over_l_range, nh_range; // sweeps over [A, B]
    int steps;
    long long histogram;
};

// A sweep's [A, B], as given.
std::optional<std::array<double, 2>> range_of(const py::object& range, const char* what)
{
    if (range.is_none()) return std::nullopt;
    const auto values = range.cast<std::vector<double>>();
    if (values.size() != 2) fail_input(fmt::format("{}: expected two numbers, [A, B]", what));
    return std::array<double, 2>{values[0], values[1]};
}

// With `snapshot`, its particles and statistics too (a series' figure).
py::dict measure(const Kernel& kernel, ParticleSet set, const Given& g, ToPython to_python,
                 SeriesSnapshot* snapshot = nullptr)
{
    ParticleArguments arguments =
        arguments_of(set, kernel, {g.h, g.support_per_h, g.masses, g.densities}, g.h_over_l, g.nh, g.volume, g.gravity);
    // A code alone: the h given, as that code stores it.
    const auto code_value = number_of(g.value, "value");
    if (g.code && !code_value) {
        arguments.stored_h_code = g.code;
        // The code's support over h, not the default of a given h (sphkern's own).
        if (g.support_per_h.is_none()) arguments.smoothing.support_per_h.reset();
    } else arguments.code = code_setting_of(g.code, code_value, particle_sources(FrontEnd::python).code);
    set_density_solve(arguments, g.neighbours_by, g.bias_correction);
    arguments.rho0 = number_of(g.rho0, "rho0");
    arguments.depth = g.depth;
    arguments.threads = g.threads;
    arguments.eta_range = range_of(g.h_over_l_range, "h_over_l_range"),
    arguments.nh_range = range_of(g.nh_range, "nh_range");
    arguments.steps = g.steps, arguments.histogram = g.histogram;
    if (arguments.eta_range || arguments.nh_range) arguments.per_particle_files = false; // a sweep returns no arrays
    ParticleAnswer answer;
    {
        py::gil_scoped_release unlocked;
        validate_particle_set(set);
        answer = analyse_particles(kernel, set,
                                   particle_request(arguments, kernel, set, particle_sources(FrontEnd::python)));
    }
    if (snapshot)
        snapshot->file = set.name, snapshot->time = set.time, snapshot->particles = answer.particles,
        snapshot->point = answer.points.front();
    py::dict out = to_python(particle_answer_json(kernel, set, answer, arguments));
    if (!answer.measures) return out; // a sweep: its points, no per-particle arrays
    const auto& m = *answer.measures;
    const std::size_t d = static_cast<std::size_t>(set.dimension);
    out["h"] = column(answer.h);
    out["volume_model"] = out["volume"]; // the document's model name, before its place takes the array
    out["volume"] = column(answer.volumes);
    auto scalar = [&](auto value) {
        py::array_t<double> values(m.size());
        for (std::size_t i = 0; i < m.size(); ++i) values.mutable_at(i) = value(i);
        return values;
    };
    out["e0"] = scalar([&](std::size_t i) { return m.scalars[i].e0; });
    out["eps_rho"] = scalar([&](std::size_t i) { return m.eps_rho_of(i); });
    out["eps_gradp"] = scalar([&](std::size_t i) { return m.scalars[i].eps_gradp; });
    out["eps_gradp_sum"] = scalar([&](std::size_t i) { return m.scalars[i].eps_gradp_sum; });
    out["e1"] = rows<3>(m.e1, d);
    out["m1"] = rows<3>(m.m1, d);
    out["E"] = tensors(m.E, set.dimension);
    py::array_t<int> neighbours(m.size());
    for (std::size_t i = 0; i < m.size(); ++i) neighbours.mutable_at(i) = m.scalars[i].neighbours;
    out["neighbours"] = neighbours;
    return out;
}

// A str, an os.PathLike, or a list or tuple of them: files, not positions.
bool is_paths(const py::object& positions)
{
    auto path = [](const py::handle& p) { return py::isinstance<py::str>(p) || py::hasattr(p, "__fspath__"); };
    if (path(positions)) return true;
    if (!py::isinstance<py::list>(positions) && !py::isinstance<py::tuple>(positions)) return false;
    const auto items = py::reinterpret_borrow<py::sequence>(positions);
    return py::len(items) > 0 && std::all_of(items.begin(), items.end(), path);
}

std::string path_of(const py::object& p)
{
    return py::str(py::module_::import("os").attr("fspath")(p)).cast<std::string>();
}

// A particle file as `particles FILE` reads it, `box` as --box.
ParticleSet read_file(const std::string& path, const py::object& box)
{
    std::optional<std::vector<double>> sides;
    if (!box.is_none()) sides = box.cast<std::vector<double>>();
    ParticleSet set;
    {
        py::gil_scoped_release unlocked;
        set = load_particle_file(path, sides, std::nullopt, std::nullopt, std::nullopt);
    }
    return set;
}

} // namespace

py::object assess_particle_file(const Kernel& kernel, const std::string& path, const FileAssess& f, ToPython to_python)
{
    if (!f.code)
        fail_input(
            "on a particle file a code's setting is assessed; expected code (and value, or none for the file's own h)");
    const CodeProfile& profile = code_profile(*f.code, ValueSource::argument("code"));
    for (const auto& [parameter, range] : f.ranges)
        if (parameter != profile.parameter)
            fail_input(fmt::format("{}_range: sweeps the {} of {}; expected code naming it, or {}_range", parameter,
                                   parameter, f.code == profile.name ? "another code" : *f.code, profile.parameter));
    const auto range = f.ranges.find(profile.parameter);
    const bool sweep = range != f.ranges.end();
    if (sweep && f.value)
        fail_input(fmt::format("{}_range: sweeps the parameter; expected no value beside it", profile.parameter));
    if (sweep && range->second.size() != 2)
        fail_input(fmt::format("{}_range: expected two numbers, [A, B]", profile.parameter));
    check_epsilon(f.epsilon, ValueSource::argument("epsilon"));
    const ParticleSet set = load_particle_file(path, f.box, f.array, std::nullopt, std::nullopt);
    ParticleSources sources = particle_sources(FrontEnd::python);
    ParticleArguments given;
    name_code(given, *f.code, sweep ? std::optional<double>(range->second[0]) : f.value);
    set_density_solve(given, f.neighbours_by, f.bias_correction);
    given.threads = f.threads;
    nlohmann::json document;
    {
        py::gil_scoped_release unlocked;
        document = sweep ? code_sweep_json(sweep_code_setting(kernel, set, given, sources, f.epsilon, range->second[0],
                                                              range->second[1], f.steps,
                                                              ValueSource::argument(profile.parameter + "_range"),
                                                              ValueSource::argument("steps")))
                         : particle_assess_document(kernel, set, given,
                                                    assess_particles(kernel, set, given, sources, f.epsilon));
    }
    return to_python(document);
}

// A run's files, each read and measured as the command line does, in the order of the times
// in their headers (the order given where one has none). With keep_going a snapshot that fails
// on its input is skipped with a RuntimeWarning naming it; with plot the series' figure is drawn.
py::list measure_series(const Kernel& kernel, const PositionsOrFiles& files, const OptionalSequence& box,
                        const Given& given, bool keep_going, const std::optional<std::string>& plot, ToPython to_python)
{
    if (plot) {
        series_figure_format(*plot, "plot");
        if (!given.h_over_l_range.is_none() || !given.nh_range.is_none())
            throw Error(ExitCode::usage,
                        "plot: a series' figure is of one setting; expected no h_over_l_range or nh_range");
    }
    std::vector<SeriesSnapshot> snapshots;
    std::vector<py::dict> documents;
    const std::size_t count = py::len(files);
    for (const auto& item : files) {
        const std::string path = path_of(py::reinterpret_borrow<py::object>(item));
        SeriesSnapshot snapshot;
        try {
            py::dict one = measure(kernel, read_file(path, box), given, to_python, &snapshot);
            one["time"] = snapshot.time ? py::object(py::float_(*snapshot.time)) : py::none();
            snapshot.given = documents.size();
            snapshots.push_back(std::move(snapshot)), documents.push_back(std::move(one));
        } catch (const Error& e) {
            if (!keep_going || e.code() != ExitCode::input) throw;
            const std::string message =
                fmt::format("skipped {}: {}", path, spelled_message(FrontEnd::python, e.what()));
            if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1) != 0) throw py::error_already_set();
        }
    }
    if (snapshots.empty())
        throw Error(ExitCode::input,
                    fmt::format("none of the {} snapshots could be measured; expected at least one", count));
    const bool by_time = order_series(snapshots);
    if (plot) draw_series_figure(*plot, "plot", series_figure_script(snapshots, by_time));
    py::list out;
    for (const auto& snapshot : snapshots) out.append(documents[snapshot.given]);
    return out;
}

void bind_particles(py::module_& m, KernelOf kernel_of, ToPython to_python)
{
    const SettingKeywords particles_keywords("particles");
    m.def(
        "particles",
        [kernel_of,
         to_python](const std::string& kernel_spec, const PositionsOrFiles& positions, const OptionalSequence& box,
                    const OptionalArrayLike& h, const OptionalFloat& support_per_h, const OptionalFloat& h_over_l,
                    const OptionalFloat& nh, const std::optional<std::string>& code, const OptionalFloat& value,
                    const std::optional<std::string>& neighbours_by, bool bias_correction,
                    const OptionalArrayLike& masses, const OptionalArrayLike& densities, const OptionalFloat& rho0,
                    const VolumeArgument& volume, const OptionalSequence& gravity, double depth, int threads,
                    const OptionalParams& params, const OptionalSequence& h_over_l_range,
                    const OptionalSequence& nh_range, int steps, long long histogram, bool keep_going,
                    const std::optional<std::string>& plot) {
            auto kernel = kernel_of(kernel_spec, params);
            const Given given{h,        support_per_h, h_over_l, nh,     code,    value, neighbours_by, bias_correction,
                              masses,   densities,     rho0,     volume, gravity, depth, threads,       h_over_l_range,
                              nh_range, steps,         histogram};
            // A file, or a run's files: each read as the command line reads it, a series in the
            // order of the times in the files' headers (the order given where one has none).
            auto typed = [](py::object result) { return py::reinterpret_steal<DictOrList>(result.release()); };
            if (plot &&
                !(is_paths(positions) && !py::isinstance<py::str>(positions) && !py::hasattr(positions, "__fspath__")))
                throw Error(ExitCode::usage, "plot: a series' figure; expected a list of a run's files as positions");
            if (!is_paths(positions)) return typed(measure(kernel, set_of(positions, box), given, to_python));
            if (py::isinstance<py::str>(positions) || py::hasattr(positions, "__fspath__"))
                return typed(measure(kernel, read_file(path_of(positions), box), given, to_python));
            return typed(measure_series(kernel, positions, box, given, keep_going, plot, to_python));
        },
        particles_keywords.required("kernel"), particles_keywords.required("positions"), py::kw_only(),
        particles_keywords("box"), particles_keywords("h"), particles_keywords("support_per_h"),
        particles_keywords("h_over_l"), particles_keywords("nh"), particles_keywords("code"),
        particles_keywords("value"), particles_keywords("neighbours_by"), particles_keywords("bias_correction"),
        particles_keywords("masses"), particles_keywords("densities"), particles_keywords("rho0"),
        particles_keywords("volume"), particles_keywords("gravity"), particles_keywords("depth"),
        particles_keywords("threads"), particles_keywords("params"), particles_keywords("h_over_l_range"),
        particles_keywords("nh_range"), particles_keywords("steps"), particles_keywords("histogram"),
        particles_keywords("keep_going"), particles_keywords("plot"), doc::particles, py::call_guard<InterruptScope>());
}

} // namespace sphkern
