// `import sphkern`: the core library for Python. Every function returns what the
// command line's --json prints (as Python objects), or numpy arrays where the input is
// an array; errors are sphkern.Error by kind (module_errors.hpp), with the command line's
// one-line message.
#include "analysis/hydrostatic_errors.hpp"
#include "analysis/resolution_axis.hpp"
#include "analysis/results_json.hpp"
#include "commands_binding.hpp"
#include "docstrings.hpp"
#include "kernels/kernel.hpp"
#include "kernels/kernel_json.hpp"
#include "kernels/kernel_registry.hpp"
#include "lattices/lattice.hpp"
#include "lattices/lattice_json.hpp"
#include "lattices/numeric_inputs.hpp"
#include "module_errors.hpp"
#include "module_support.hpp"
#include "particles/sources/particle_source.hpp"
#include "particles_binding.hpp"
#include "python_arrays.hpp"
#include "python_types.hpp"
#include "requests/assess_request.hpp"
#include "requests/design_request.hpp"
#include "requests/eps_request.hpp"
#include "requests/kernels_request.hpp"
#include "requests/lattices_request.hpp"
#include "requests/particles_request.hpp"
#include "requests/roots_request.hpp"
#include "requests/settings/command_settings.hpp"
#include "requests/shells_request.hpp"
#include "requests/stability_request.hpp"
#include "requests/surface_request.hpp"
#include "setting_keywords.hpp"
#include "stability/stability_scan.hpp"
#include "support/error.hpp"
#include "support/io/install_paths.hpp"
#include "support/process/interruption.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <dlfcn.h>

#include <cmath>
#include <mutex>
#include <optional>
#include <thread>

namespace py = pybind11;
using namespace sphkern;

#ifndef SPHKERN_PYTHON_TO_PREFIX
#define SPHKERN_PYTHON_TO_PREFIX "../../.."
#endif

namespace {

// Gravity as given: none (the lattice's) or a sequence of `dimension` numbers.
std::optional<std::vector<double>> gravity_input(const py::object& gravity, int dimension)
{
    if (gravity.is_none()) return std::nullopt;
    try {
        return gravity.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
        fail_input("gravity: expected a sequence of " + std::to_string(dimension) + " numbers");
    }
}

EvaluationSources argument_sources()
{
    return {ValueSource::argument("gravity"), ValueSource::argument("site"), ValueSource::argument("shells")};
}

// `shells`: the radii summed over (in d; none: every shell inside the support), and the
// kernel's formula past its support with them, as --shells and --continue-past-support.
EvaluationInputs evaluation_of(const Lattice& lattice, const py::object& a_p, const py::object& gravity, int site,
                               const py::object& shells = py::none(), bool continue_past_support = false)
{
    EvaluationInputs inputs;
    inputs.a_p = ap_input(a_p);
    inputs.gravity = gravity_input(gravity, lattice.dimension);
    inputs.site = site;
    if (!shells.is_none()) {
        const DoubleArray radii = real_array(shells, "shells", "a sequence of shell radii");
        inputs.shell_radii.assign(radii.data(), radii.data() + radii.size());
    }
    inputs.continue_past_support = continue_past_support;
    return inputs;
}

py::dict eps(const std::string& kernel_spec, const std::string& lattice_spec, const ArrayLike& k_values,
             const NameOrNumber& a_p, const OptionalSequence& gravity, int site, const OptionalParams& params,
             const std::string& axis, const OptionalSequence& shells, bool continue_past_support)
{
    const DoubleArray k = real_array(k_values, "k", "a number or an array of numbers");
    auto lattice = load_lattice(lattice_spec);
    auto kernel = kernel_of(kernel_spec, params);
    EpsRequest request;
    request.k.assign(k.data(), k.data() + k.size());
    request.axis = parse_axis(axis, "axis");
    request.evaluation = evaluation_of(lattice, a_p, gravity, site, shells, continue_past_support);
    const EpsSources sources{ValueSource::argument("k"), ValueSource::argument("axis"), argument_sources(),
                             ValueSource::argument("code"), ValueSource::argument("value")};
    check_eps_request(request, sources);
    std::vector<ErrorValues> values;
    {
        py::gil_scoped_release unlocked; // one C++ loop over the whole array
        values = run_eps_series(request, sources, kernel, lattice);
    }
    std::vector<py::ssize_t> shape(k.shape(), k.shape() + k.ndim());
    py::array_t<double> rho(shape), gradp(shape), lateral(shape);
    py::array_t<long long> nh(shape);
    double *r = rho.mutable_data(), *gp = gradp.mutable_data(), *l = lateral.mutable_data();
    long long* h = nh.mutable_data();
    for (std::size_t i = 0; i < values.size(); ++i) {
        r[i] = values[i].eps_rho;
        gp[i] = values[i].eps_gradp;
        l[i] = values[i].lateral;
        h[i] = values[i].neighbours;
    }
    py::dict out;
    out["eps_rho"] = rho;
    out["eps_gradp"] = gradp;
    out["eps_lateral"] = lateral;
    out["nh"] = nh;
    return out;
}

py::dict surface(const std::string& kernel_spec, const std::string& lattice_spec, std::optional<double> k,
                 const std::optional<std::string>& code, std::optional<double> value, const std::string& form,
                 int layers, const NameOrNumber& a_p, const OptionalSequence& gravity, int site,
                 const OptionalParams& params, std::optional<int> termination)
{
    const CodeSettingSources code_sources{ValueSource::argument("code"), ValueSource::argument("value")};
    SurfaceRequest request;
    request.code = code_setting_of(code, value, code_sources);
    if (k.has_value() == request.code.has_value())
        throw Error(ExitCode::input, k ? "give one of k and code" : "k: expected a number, or code and value");
    if (k) request.k = *k;
    auto lattice = load_lattice(lattice_spec);
    auto kernel = kernel_of(kernel_spec, params);
    request.layers = layers;
    request.evaluation = evaluation_of(lattice, a_p, gravity, site);
    request.form = parse_gradient_form(form);
    if (termination && *termination < 0)
        fail_input(fmt::format("termination: {}: expected an index, 0 or more", *termination));
    request.termination = termination;
    const SurfaceSources sources{ValueSource::argument("k"), argument_sources(), ValueSource::argument("layers"),
                                 code_sources.code, code_sources.value};
    check_surface_request(request, sources);
    const auto result = run_surface(request, sources, kernel, lattice);
    return to_python(surface_request_document(request, result, kernel, lattice));
}

// The roots request from its arguments: the texts as types, the stability model checked with or without `stability`.
RootsRequest roots_request(double kmin, double kmax, double epsilon, bool lateral, const std::string& axis,
                           bool stability, double gamma, int steps, double horizon, const std::string& h_model,
                           const std::optional<std::string>& convention, const std::optional<std::string>& code,
                           int threads)
{
    RootsRequest r;
    r.window_min = kmin;
    r.window_max = kmax;
    r.axis = parse_axis(axis, "axis");
    r.epsilon = epsilon;
    r.lateral = lateral;
    r.stability = stability;
    r.model = {gamma, horizon, steps, parse_h_model(h_model, "h_model"), threads};
    // convention is the old name of code: the same answer, with the code's own density.
    if (convention && code) throw Error(ExitCode::input, "give one of code and convention (its old name)");
    if (code || convention)
        r.code = &code_profile(code ? *code : *convention, ValueSource::argument(code ? "code" : "convention"));
    return r;
}

// The whole document of `roots --json`, whatever the options: they only add keys to it.
py::dict roots(const std::string& kernel_spec, const std::string& lattice_spec, double kmin, double kmax,
               const NameOrNumber& a_p, const OptionalSequence& gravity, int site, const OptionalParams& params,
               double epsilon, bool lateral, const std::string& axis, bool stability, double gamma, int steps,
               double horizon, const std::string& h_model, const std::optional<std::string>& convention,
               const std::optional<std::string>& code, const OptionalSequence& shells, bool continue_past_support,
               int threads)
{
    auto request = roots_request(kmin, kmax, epsilon, lateral, axis, stability, gamma, steps, horizon, h_model,
                                 convention, code, threads);
    RootsSources sources{ValueSource::argument("kmin/kmax"), ValueSource::argument("epsilon"),
                         ValueSource::argument("gamma"),     ValueSource::argument("horizon"),
                         ValueSource::argument("steps"),     argument_sources()};
    check_roots_request(request, sources);
    auto lattice = load_lattice(lattice_spec);
    auto kernel = kernel_of(kernel_spec, params);
    request.evaluation = evaluation_of(lattice, a_p, gravity, site, shells, continue_past_support);
    sources.evaluation = argument_sources();
    nlohmann::json document;
    {
        py::gil_scoped_release unlocked;
        const auto result = run_roots(request, sources, kernel, lattice);
        document = roots_request_document(request, result, kernel, lattice);
    }
    return to_python(document);
}

py::dict design(const std::string& kernel_spec, const std::string& lattice_spec, const std::string& param,
                const OptionalSequence& range, double kmin, double kmax, const NameOrNumber& a_p,
                const OptionalSequence& gravity, int site, const OptionalParams& params, int threads)
{
    DesignRequest request;
    request.parameter = param;
    request.threads = threads;
    request.k_min = kmin;
    request.k_max = kmax;
    DesignSources sources{ValueSource::argument("kmin/kmax"), argument_sources()};
    check_design_request(request, sources);
    auto lattice = load_lattice(lattice_spec);
    auto kernel = kernel_of(kernel_spec, params);
    request.evaluation = evaluation_of(lattice, a_p, gravity, site);
    sources.evaluation = argument_sources();
    if (!range.is_none()) {
        const auto r = range.cast<std::vector<double>>();
        if (r.size() != 2) fail_input("range: expected two numbers [min, max]");
        request.range = std::pair(r[0], r[1]);
    }
    DesignOutcome outcome;
    {
        py::gil_scoped_release unlocked;
        outcome = run_design(request, sources, kernel, lattice);
    }
    return to_python(design_json(kernel, outcome.problem, outcome.result));
}

// A kernel's functions, vectorised over q.
class KernelHandle {
public:
    explicit KernelHandle(Kernel kernel) : kernel_(std::move(kernel)) {}
    std::string name() const { return kernel_.name(); }
    double support() const { return kernel_.support(); }
    py::dict info() const { return to_python(kernel_json(kernel_.definition())); }
    py::array_t<double> w(const ArrayLike& q, int dim, double k) const { return apply(q, dim, k, false); }
    py::array_t<double> dw(const ArrayLike& q, int dim, double k) const { return apply(q, dim, k, true); }

private:
    py::array_t<double> apply(const ArrayLike& values, int dim, double k, bool derivative) const
    {
        const DoubleArray q = real_array(values, "q", "a number or an array of numbers");
        check_k(k, ValueSource::argument("k"));
        kernel_.require_dimension(dim, std::to_string(dim) + "D space");
        std::vector<py::ssize_t> shape(q.shape(), q.shape() + q.ndim());
        py::array_t<double> out(shape);
        const std::size_t n = static_cast<std::size_t>(q.size());
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isfinite(q.data()[i]) || q.data()[i] < 0)
                fail_input(fmt::format("q = {} is not allowed, expected q >= 0", q.data()[i]));
        {
            py::gil_scoped_release unlocked;
            if (derivative) kernel_.dw_batch(q.data(), out.mutable_data(), n, dim, k);
            else kernel_.w_batch(q.data(), out.mutable_data(), n, dim, k);
        }
        return out;
    }
    Kernel kernel_;
};

// The module's own folder: its build tree's plugins are beside it, an installed one's under its prefix.
std::filesystem::path module_folder()
{
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&module_folder), &info) == 0 || !info.dli_fname) return {};
    return std::filesystem::absolute(info.dli_fname).parent_path();
}

// The adapter: the arguments as given (0 grid or path: none); the request checks them and which go together.
StabilityRequest stability_request(std::optional<double> k, double gamma,
                                   const std::optional<std::vector<double>>& wavevector, std::optional<double> kmin,
                                   std::optional<double> kmax, int steps, int grid, int path, int threads,
                                   double horizon, const std::string& h_model, const std::optional<std::string>& code)
{
    StabilityRequest r;
    if (code) {
        if (!kmin) fail_input("code gives the stable intervals over k in a code's setting; expected kmin and kmax");
        r.code = &code_profile(*code, ValueSource::argument("code"));
    }
    r.h_model = parse_h_model(h_model, "h_model");
    r.k = k;
    r.k_min = kmin;
    r.k_max = kmax;
    r.wavevector = wavevector;
    r.steps = steps;
    if (path != 0) r.path_points = path;
    r.gamma = gamma;
    r.horizon = horizon;
    if (grid != 0) r.grid = grid;
    r.threads = threads;
    return r;
}

} // namespace

namespace {

using Guard = py::call_guard<InterruptScope>;

// Every kernel and lattice, and files loaded into the module.
void bind_catalogues(py::module_& m, const Guard& guard)
{
    m.def(
        "kernels",
        []() -> py::list {
            std::lock_guard lock(registry_mutex());
            return to_python(kernels_listing(registry()));
        },
        doc::kernels, guard);
    m.def(
        "lattices", []() -> py::list { return to_python(lattices_listing()); }, doc::lattices, guard);
    m.def(
        "load_plugin",
        [](const std::string& path) -> py::dict {
            std::lock_guard lock(registry_mutex());
            return to_python(kernel_json(*registry().find(path)));
        },
        py::arg("path"), doc::load_plugin, guard);
    m.def(
        "load_lattice", [](const std::string& path) -> py::dict { return to_python(lattice_json(read_lattice(path))); },
        py::arg("path"), doc::load_lattice, guard);
}

// The hydrostatic errors at k, the neighbour shells and the surface profile.
void bind_accuracy(py::module_& m, const Guard& guard)
{
    const SettingKeywords eps_keywords("eps");
    m.def("eps", &eps, eps_keywords.required("kernel"), eps_keywords.required("lattice"), eps_keywords.required("k"),
          py::kw_only(), eps_keywords("a_p"), eps_keywords("gravity"), eps_keywords("site"), eps_keywords("params"),
          eps_keywords("axis"), eps_keywords("shells"), eps_keywords("continue_past_support"), doc::eps, guard);
    m.def(
        "code_k",
        [](const std::string& kernel_spec, const std::string& lattice_spec, const std::string& code, double value,
           const NameOrNumber& a_p, int site, const OptionalParams& params) {
            auto lattice = load_lattice(lattice_spec);
            auto kernel = kernel_of(kernel_spec, params);
            EpsRequest request;
            request.code = CodeSetting{code, value};
            request.evaluation = evaluation_of(lattice, a_p, py::none(), site);
            const EpsSources sources{ValueSource::argument("k"), ValueSource::argument("axis"), argument_sources(),
                                     ValueSource::argument("code"), ValueSource::argument("value")};
            check_eps_request(request, sources);
            py::gil_scoped_release unlocked;
            return run_eps_at_k(request, sources, kernel, lattice).k;
        },
        // eps --code's setting, as Python gives it: eps's rows but code and value, required here.
        eps_keywords.required("kernel"), eps_keywords.required("lattice"), py::arg("code"), py::arg("value"),
        py::kw_only(), eps_keywords("a_p"), eps_keywords("site"), eps_keywords("params"), doc::code_k, guard);
    const SettingKeywords shells_keywords("shells");
    m.def(
        "shells",
        [](const std::string& lattice_spec, double radius, int site, const OptionalSequence& gravity) -> py::dict {
            auto lattice = load_lattice(lattice_spec);
            const ShellsRequest request{radius, site, gravity_input(gravity, lattice.dimension)};
            return to_python(shells_json(run_shells(request, shells_sources(FrontEnd::python), lattice)));
        },
        shells_keywords.required("lattice"), shells_keywords.required("radius"), shells_keywords("site"),
        shells_keywords("gravity"), doc::shells, guard);
    const SettingKeywords surface_keywords("surface");
    m.def("surface", &surface, surface_keywords.required("kernel"), surface_keywords.required("lattice"),
          surface_keywords("k"), py::kw_only(), surface_keywords("code"), surface_keywords("value"),
          surface_keywords("form"), surface_keywords("layers"), surface_keywords("a_p"), surface_keywords("gravity"),
          surface_keywords("site"), surface_keywords("params"), surface_keywords("termination"), doc::surface, guard);
}

// The roots in k of both errors, with stability and a code's convention on request.
void bind_roots(py::module_& m, const Guard& guard)
{
    const SettingKeywords roots_keywords("roots");
    m.def("roots", &roots, roots_keywords.required("kernel"), roots_keywords.required("lattice"), py::kw_only(),
          roots_keywords("kmin"), roots_keywords("kmax"), roots_keywords("a_p"), roots_keywords("gravity"),
          roots_keywords("site"), roots_keywords("params"), roots_keywords("epsilon"), roots_keywords("lateral"),
          roots_keywords("axis"), roots_keywords("stability"), roots_keywords("gamma"), roots_keywords("steps"),
          roots_keywords("horizon"), roots_keywords("h_model"), roots_keywords("convention"), roots_keywords("code"),
          roots_keywords("shells"), roots_keywords("continue_past_support"), roots_keywords("threads"), doc::roots,
          guard);
}

// The assess request of the keywords: k, or a code and its value; the window, the tolerance
// and the stability's settings.
// Whether an assess keyword holds its declared default.
bool is_default(const char* key, double value) { return value == std::stod(settings_of("assess")[key].fallback); }

AssessRequest assess_request_of(std::optional<double> k, const std::optional<std::string>& code,
                                std::optional<double> value, double kmin, double kmax, double epsilon, double gamma,
                                std::optional<double> coef_sound, double horizon, int threads, std::size_t glass)
{
    AssessRequest request;
    if (k.has_value() == (code.has_value() || value.has_value()))
        fail_input("give k, or code and value (a code's own setting)");
    if (code.has_value() != value.has_value()) fail_input("give code and value together");
    if (k) request.setting.k = {*k};
    if (code) request.setting.code = CodeSetting{*code, *value};
    request.window_min = kmin, request.window_max = kmax;
    request.epsilon = epsilon, request.gamma = gamma, request.horizon = horizon, request.coef_sound = coef_sound;
    request.threads = threads, request.glass = glass;
    return request;
}

// One verdict on a setting on a lattice, its document as Python objects.
py::dict assess_on_lattice(const std::string& kernel_spec, const std::string& lattice_spec,
                           const OptionalParams& params, AssessRequest request, const NameOrNumber& a_p,
                           const OptionalSequence& gravity, int site, const OptionalSequence& shells,
                           bool continue_past_support)
{
    AssessSources sources{{ValueSource::argument("k"), ValueSource::argument("axis"), argument_sources(),
                           ValueSource::argument("code"), ValueSource::argument("value")},
                          ValueSource::argument("kmin/kmax"),
                          ValueSource::argument("epsilon"),
                          ValueSource::argument("gamma"),
                          ValueSource::argument("horizon")};
    auto lattice = load_lattice(lattice_spec);
    auto kernel = kernel_of(kernel_spec, params);
    request.setting.evaluation = evaluation_of(lattice, a_p, gravity, site, shells, continue_past_support);
    check_assess_request(request, sources);
    nlohmann::json document;
    {
        py::gil_scoped_release unlocked;
        document = assess_document(request, run_assess(request, sources, kernel, lattice));
    }
    return to_python(document);
}

// One verdict on a setting: k, or a code's own (`sphkern assess`).
void bind_assess(py::module_& m, const Guard& guard)
{
    const SettingKeywords assess_keywords("assess");
    m.def(
        "assess",
        [](const std::string& kernel_spec, const NameOrPath& lattice_or_file, std::optional<double> k,
           std::optional<std::string> code, std::optional<double> value, double kmin, double kmax, double epsilon,
           double gamma, std::optional<double> coef_sound, double horizon, const NameOrNumber& a_p,
           const OptionalSequence& gravity, int site, const OptionalParams& params, const OptionalSequence& box,
           std::optional<std::string> array, std::optional<std::string> neighbours_by, bool bias_correction,
           int threads, int steps, const OptionalSequence& eta_range, const OptionalSequence& hfact_range,
           const OptionalSequence& nngb_range, const OptionalSequence& hdx_range, const OptionalSequence& coefh_range,
           const OptionalSequence& particle_radius_range, const OptionalSequence& shells, bool continue_past_support,
           std::size_t glass) -> py::dict {
            const auto lattice_spec =
                py::str(py::module_::import("os").attr("fspath")(lattice_or_file)).cast<std::string>();
            if (source_kind(lattice_spec) == SourceKind::file) {
                // The lattice's keywords mean nothing on a particle set: said, not ignored.
                const bool lattice_keywords =
                    k || coef_sound || glass || !gravity.is_none() || !shells.is_none() || continue_past_support ||
                    !is_default("kmin", kmin) || !is_default("kmax", kmax) || !is_default("gamma", gamma) ||
                    !is_default("horizon", horizon) || site != 0 ||
                    !(py::isinstance<py::str>(a_p) && a_p.cast<std::string>() == settings_of("assess")["a_p"].fallback);
                if (lattice_keywords)
                    fail_input(fmt::format(
                        "k, kmin, kmax, gamma, coef_sound, horizon, a_p, gravity, site, shells and glass are for a "
                        "lattice; on a particle file ({}) assess judges the set's own sums, expected none",
                        lattice_spec));
                FileAssess f{code, value, epsilon, {}, array, neighbours_by, bias_correction, threads, steps, {}};
                if (!box.is_none()) f.box = box.cast<std::vector<double>>();
                const std::pair<const char*, const OptionalSequence*> ranges[] = {
                    {"eta", &eta_range}, {"hfact", &hfact_range}, {"nngb", &nngb_range},
                    {"hdx", &hdx_range}, {"coefh", &coefh_range}, {"particle_radius", &particle_radius_range}};
                for (const auto& [name, range] : ranges)
                    if (!range->is_none()) f.ranges[name] = range->cast<std::vector<double>>();
                return assess_particle_file(kernel_of(kernel_spec, params), lattice_spec, f, &to_python);
            }
            if (!box.is_none() || array || neighbours_by || bias_correction || !is_default("steps", steps) ||
                !eta_range.is_none() || !hfact_range.is_none() || !nngb_range.is_none() || !hdx_range.is_none() ||
                !coefh_range.is_none() || !particle_radius_range.is_none())
                fail_input(fmt::format("box, array, neighbours_by, bias_correction, steps and the parameter ranges "
                                       "are for a particle file; {} is a lattice, expected none",
                                       lattice_spec));
            return assess_on_lattice(kernel_spec, lattice_spec, params,
                                     assess_request_of(k, code, value, kmin, kmax, epsilon, gamma, coef_sound, horizon,
                                                       threads, glass),
                                     a_p, gravity, site, shells, continue_past_support);
        },
        assess_keywords.required("kernel"), assess_keywords.required("lattice"), py::kw_only(), assess_keywords("k"),
        assess_keywords("code"), assess_keywords("value"), assess_keywords("kmin"), assess_keywords("kmax"),
        assess_keywords("epsilon"), assess_keywords("gamma"), assess_keywords("coef_sound"), assess_keywords("horizon"),
        assess_keywords("a_p"), assess_keywords("gravity"), assess_keywords("site"), assess_keywords("params"),
        assess_keywords("box"), assess_keywords("array"), assess_keywords("neighbours_by"),
        assess_keywords("bias_correction"), assess_keywords("threads"), assess_keywords("steps"),
        assess_keywords("eta_range"), assess_keywords("hfact_range"), assess_keywords("nngb_range"),
        assess_keywords("hdx_range"), assess_keywords("coefh_range"), assess_keywords("particle_radius_range"),
        assess_keywords("shells"), assess_keywords("continue_past_support"), assess_keywords("glass"), doc::assess,
        guard);
}

// Linear stability through the one stability request.
void bind_stability(py::module_& m, const Guard& guard)
{
    const SettingKeywords stability_keywords("stability");
    m.def(
        "stability",
        [](const std::string& kernel_spec, const std::string& lattice_spec, std::optional<double> k, double gamma,
           std::optional<std::vector<double>> wavevector, std::optional<double> kmin, std::optional<double> kmax,
           int steps, int grid, int path, int threads, double horizon, const OptionalParams& params,
           const std::string& h_model, const std::optional<std::string>& code) -> py::dict {
            const auto request =
                stability_request(k, gamma, wavevector, kmin, kmax, steps, grid, path, threads, horizon, h_model, code);
            const StabilitySources sources{ValueSource::argument("k"),       ValueSource::argument("kmin"),
                                           ValueSource::argument("kmax"),    ValueSource::argument("gamma"),
                                           ValueSource::argument("horizon"), ValueSource::argument("wavevector"),
                                           ValueSource::argument("steps"),   ValueSource::argument("grid"),
                                           ValueSource::argument("path"),    ""};
            check_stability_request(request, sources);
            auto lattice = load_lattice(lattice_spec);
            auto kernel = kernel_of(kernel_spec, params);
            nlohmann::json document;
            {
                py::gil_scoped_release unlocked;
                document = stability_json(run_stability(request, sources, kernel, lattice));
            }
            return to_python(document);
        },
        stability_keywords.required("kernel"), stability_keywords.required("lattice"), stability_keywords("k"),
        py::kw_only(), stability_keywords("gamma"), stability_keywords("wavevector"), stability_keywords("kmin"),
        stability_keywords("kmax"), stability_keywords("steps"), stability_keywords("grid"), stability_keywords("path"),
        stability_keywords("threads"), stability_keywords("horizon"), stability_keywords("params"),
        stability_keywords("h_model"), stability_keywords("code"), doc::stability, guard);
}

// Kernel design: where both errors vanish.
void bind_design(py::module_& m, const Guard& guard)
{
    const SettingKeywords design_keywords("design");
    m.def("design", &design, design_keywords.required("kernel"), design_keywords.required("lattice"),
          design_keywords.required("param"), py::kw_only(), design_keywords("range"), design_keywords("kmin"),
          design_keywords("kmax"), design_keywords("a_p"), design_keywords("gravity"), design_keywords("site"),
          design_keywords("params"), design_keywords("threads"), doc::design, guard);
}

// A kernel as an object, its functions vectorised over q.
void bind_kernel(py::module_& m, const Guard& guard)
{
    py::class_<KernelHandle>(m, "Kernel", doc::kernel_class)
        .def_property_readonly("name", &KernelHandle::name, doc::kernel_name)
        .def_property_readonly("support", &KernelHandle::support, doc::kernel_support)
        .def_property_readonly("info", &KernelHandle::info, doc::kernel_info)
        .def("w", &KernelHandle::w, py::arg("q"), py::arg("dim"), py::arg("k") = 1.0, doc::kernel_w.c_str(), guard)
        .def("dw", &KernelHandle::dw, py::arg("q"), py::arg("dim"), py::arg("k") = 1.0, doc::kernel_dw.c_str(), guard);
    m.def(
        "kernel",
        [](const std::string& spec, const OptionalParams& params) { return KernelHandle(kernel_of(spec, params)); },
        py::arg("name"), py::arg("params") = py::none(), doc::kernel, guard);
}

} // namespace

PYBIND11_MODULE(sphkern, m)
{
    m.doc() = doc::module;
    m.attr("__version__") = SPHKERN_VERSION;
    const auto folder = module_folder();
    set_home(folder.parent_path(), (folder / SPHKERN_PYTHON_TO_PREFIX).lexically_normal());
    bind_errors(m);
    // Every call runs with sphkern's signal handlers, Python's own before and after it.
    const Guard guard;
    bind_particles(m, &kernel_of, &to_python);
    bind_catalogues(m, guard);
    bind_accuracy(m, guard);
    bind_roots(m, guard);
    bind_assess(m, guard);
    bind_stability(m, guard);
    bind_design(m, guard);
    bind_kernel(m, guard);
    bind_kernel_commands(m);
    bind_relax(m);
    bind_studies(m);
    bind_read_particles(m);
}
