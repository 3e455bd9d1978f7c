// sphkern.check, spectrum, block and pairing: each the request its command runs, with the
// arguments named as the command's options and its --json document as Python objects.
#include "commands_binding.hpp"
#include "command_docstrings.hpp"
#include "module_errors.hpp"
#include "module_support.hpp"
#include "python_types.hpp"
#include "setting_keywords.hpp"

#include "lattices/lattice.hpp"
#include "requests/block_request.hpp"
#include "requests/check_request.hpp"
#include "requests/pairing_request.hpp"
#include "requests/relax_report.hpp"
#include "requests/spectrum_request.hpp"
#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/output_targets.hpp"
#include "support/process/interruption.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace sphkern {

namespace {

// None, one text or a sequence of texts.
std::vector<std::string> texts_of(const py::object& given, const char* what, const char* expected)
{
    if (given.is_none()) return {};
    if (py::isinstance<py::str>(given)) return {given.cast<std::string>()};
    try {
        return given.cast<std::vector<std::string>>();
    } catch (const py::cast_error&) {
        fail_input(fmt::format("{}: expected {}", what, expected));
    }
}

py::list check_command(const OptionalNames& kernel, bool all, bool strict, double timeout, const OptionalNames& plugin,
                       const OptionalParams& params)
{
    CheckRequest request;
    request.names = texts_of(kernel, "kernel", "a kernel name or file, or a sequence of them");
    for (const auto& file : texts_of(plugin, "plugin", "a plugin file, or a sequence of them"))
        request.plugins.emplace_back(file);
    request.all = all;
    request.strict = strict;
    request.timeout = timeout;
    check_check_request(request, check_sources(FrontEnd::python));
    request.parameters = parameters_of(params);
    auto registry = check_registry(request);
    const auto kernels = kernels_to_check(request, registry);
    py::list results;
    std::vector<std::string> failed;
    for (const auto& kernel : kernels) {
        const auto checked = run_check(request, kernel);
        if (check_fails(checked, request.strict)) failed.push_back(kernel.label());
        results.append(to_python(checked.document));
    }
    if (!failed.empty()) {
        std::string names;
        for (const auto& name : failed) names += (names.empty() ? "" : ", ") + name;
        raise_check_failed(fmt::format("check: {} failed{}; the checks are on this error's results", names,
                                       request.strict ? " (strict: a warning fails too)" : ""),
                           results);
    }
    return results;
}

py::dict spectrum_command(const std::string& kernel_spec, int dim, double k, double kh_max, int points,
                          const OptionalParams& params)
{
    const SpectrumRequest request{dim, k, kh_max, points};
    const SpectrumSources sources{value_named(FrontEnd::python, "dim"), value_named(FrontEnd::python, "k"),
                                  value_named(FrontEnd::python, "max"), value_named(FrontEnd::python, "points")};
    check_spectrum_request(request, sources);
    const auto kernel = kernel_of(kernel_spec, params);
    SpectrumResult result;
    {
        py::gil_scoped_release unlocked;
        result = run_spectrum(request, sources, kernel);
    }
    py::dict out = to_python(spectrum_document(request, result, kernel));
    py::array_t<double> curve({result.curve.size(), std::size_t{2}});
    auto view = curve.mutable_unchecked<2>();
    for (std::size_t i = 0; i < result.curve.size(); ++i)
        view(i, 0) = result.curve[i].first, view(i, 1) = result.curve[i].second;
    out["curve"] = curve;
    return out;
}

template <class T>
py::array_t<T> column(const HugeArray<T>& values)
{
    py::array_t<T> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out.mutable_at(i) = values[i];
    return out;
}

py::dict block_command(const std::string& kernel_spec, const std::string& lattice_spec, double k,
                       const IntSequence& size, bool periodic, const std::string& form, int threads,
                       const NameOrNumber& a_p, const std::optional<std::string>& vtk,
                       const std::optional<std::string>& csv, const OptionalParams& params)
{
    std::vector<OutputTarget> outputs;
    if (vtk) outputs.push_back({"vtk", *vtk});
    if (csv) outputs.push_back({"csv", *csv});
    std::vector<std::string> inputs;
    for (const auto& spec : {lattice_spec, kernel_spec})
        if (std::filesystem::exists(spec)) inputs.push_back(spec);
    check_output_targets(outputs, inputs);
    BlockRequest request;
    request.k = k;
    try {
        request.cells = size.cast<std::vector<long long>>();
    } catch (const py::cast_error&) {
        fail_input("size: expected whole numbers of cells [N1, N2] or [N1, N2, N3]");
    }
    request.periodic = periodic;
    request.form = parse_gradient_form(form);
    request.threads = threads;
    request.a_p = ap_input(a_p);
    const BlockSources sources{value_named(FrontEnd::python, "size"), value_named(FrontEnd::python, "threads"),
                               value_named(FrontEnd::python, "k")};
    check_block_request(request, sources);
    const auto lattice = load_lattice(lattice_spec);
    const auto kernel = kernel_of(kernel_spec, params);
    BlockRun run;
    {
        py::gil_scoped_release unlocked;
        run = run_block(request, sources, kernel, lattice);
        if (vtk) write_file_atomically(*vtk, [&](std::ostream& o) { write_block_vtk(o, run.result); });
        if (csv) write_file_atomically(*csv, [&](std::ostream& o) { write_block_csv(o, run.result); });
    }
    const auto& result = run.result;
    py::dict out = to_python(block_document(run, kernel, lattice));
    const std::size_t n = result.particles(), d = static_cast<std::size_t>(result.dimension);
    py::array_t<double> positions({n, d});
    auto view = positions.mutable_unchecked<2>();
    for (std::size_t i = 0; i < n; ++i) {
        view(i, 0) = result.x[i], view(i, 1) = result.y[i];
        if (d == 3) view(i, 2) = result.z[i];
    }
    out["positions"] = positions;
    out["layer"] = column(result.layer);
    out["eps_rho"] = column(result.eps_rho);
    out["eps_gradp"] = column(result.eps_gradp);
    return out;
}

py::dict pairing_command(const std::string& kernel_spec, const std::string& lattice_spec, std::optional<double> k,
                         const std::optional<std::string>& code, std::optional<double> value,
                         std::optional<double> kmin, std::optional<double> kmax, int samples, double noise,
                         double duration, double damping, double dt, double gamma, double horizon,
                         unsigned long long seed, int threads, const OptionalParams& params)
{
    const CodeSettingSources code_sources{value_named(FrontEnd::python, "code"),
                                          value_named(FrontEnd::python, "value")};
    const auto setting = code_setting_of(code, value, code_sources);
    const bool range = kmin || kmax;
    if ((k || setting) == range) fail_input("give k (or code and value), or kmin and kmax");
    if (k && setting) fail_input("give one of k and code");
    if (range && !(kmin && kmax)) fail_input("a range needs both kmin and kmax");
    PairingRequest request;
    // A code's k is known once the kernel and lattice are: checked then, as one k.
    request.k_min = range ? *kmin : setting ? 1 : *k;
    request.k_max = range ? *kmax : setting ? 1 : *k;
    request.samples = range ? samples : 1;
    request.noise = noise, request.duration = duration, request.damping = damping, request.time_step = dt;
    request.gamma = gamma, request.horizon = horizon, request.seed = seed, request.threads = threads;
    check_pairing_request(request, pairing_sources(FrontEnd::python));
    const auto lattice = load_lattice(lattice_spec);
    const auto kernel = kernel_of(kernel_spec, params);
    nlohmann::json document;
    {
        py::gil_scoped_release unlocked;
        const auto code_k = pairing_code_k(request, setting, code_sources, kernel, lattice);
        const auto points = pairing_motion(kernel, lattice, request);
        document = pairing_json(kernel, lattice, request, points, code_k);
    }
    return to_python(document);
}

} // namespace

void bind_kernel_commands(py::module_& m)
{
    const py::call_guard<InterruptScope> guard;
    const SettingKeywords check_keywords("check");
    m.def("check", &check_command, check_keywords("kernel"), py::kw_only(), check_keywords("all"),
          check_keywords("strict"), check_keywords("timeout"), check_keywords("plugin"), check_keywords("params"),
          doc::check, guard);
    const SpectrumRequest spectrum_defaults;
    const SettingKeywords spectrum_keywords("spectrum");
    m.def("spectrum", &spectrum_command, spectrum_keywords.required("kernel"), spectrum_keywords.required("dim"),
          py::kw_only(), spectrum_keywords("k"), spectrum_keywords("max"), spectrum_keywords("points"),
          spectrum_keywords("params"), doc::spectrum, guard);
    const SettingKeywords block_keywords("block");
    m.def("block", &block_command, block_keywords.required("kernel"), block_keywords.required("lattice"),
          block_keywords.required("k"), block_keywords.required("size"), py::kw_only(), block_keywords("periodic"),
          block_keywords("form"), block_keywords("threads"), block_keywords("a_p"), block_keywords("vtk"),
          block_keywords("csv"), block_keywords("params"), doc::block, guard);
    const PairingRequest pairing_defaults;
    const SettingKeywords pairing_keywords("pairing");
    m.def("pairing", &pairing_command, pairing_keywords.required("kernel"), pairing_keywords.required("lattice"),
          pairing_keywords("k"), py::kw_only(), pairing_keywords("code"), pairing_keywords("value"),
          pairing_keywords("kmin"), pairing_keywords("kmax"), pairing_keywords("samples"), pairing_keywords("noise"),
          pairing_keywords("duration"), pairing_keywords("damping"), pairing_keywords("dt"), pairing_keywords("gamma"),
          pairing_keywords("horizon"), pairing_keywords("seed"), pairing_keywords("threads"),
          pairing_keywords("params"), doc::pairing, guard);
}

} // namespace sphkern
