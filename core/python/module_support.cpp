#include "module_support.hpp"

#include "requests/source_request.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <map>

namespace py = pybind11;

namespace sphkern {

std::map<std::string, double> parameters_of(const py::object& params)
{
    std::map<std::string, double> values;
    if (params.is_none()) return values;
    if (!py::isinstance<py::dict>(params)) fail_input("params: expected a dict of parameter names to numbers");
    for (const auto& [name, value] : params.cast<py::dict>()) {
        auto key = py::str(name).cast<std::string>();
        try {
            values[key] = value.cast<double>();
        } catch (const py::cast_error&) {
            fail_input("params: \"" + key + "\" must be a number");
        }
    }
    return values;
}

std::mutex& registry_mutex()
{
    static std::mutex mutex;
    return mutex;
}

KernelRegistry& registry()
{
    static KernelRegistry r = KernelRegistry::discover({});
    return r;
}

Kernel kernel_of(const std::string& spec, const py::object& params)
{
    auto values = parameters_of(params);
    std::lock_guard lock(registry_mutex());
    return Kernel(registry().find(spec), values);
}

VolumeCoefficientInput ap_input(const py::object& a_p)
{
    if (py::isinstance<py::str>(a_p)) return a_p.cast<std::string>();
    try {
        return a_p.cast<double>();
    } catch (const py::cast_error&) {
        fail_input("a_p: expected a name the lattice offers or a positive number");
    }
}

py::object to_python(const nlohmann::json& document)
{
    return py::module_::import("json").attr("loads")(document.dump());
}

pybind11::array_t<double> positions_array(const ParticleSet& set)
{
    const std::size_t n = set.size(), d = static_cast<std::size_t>(set.dimension);
    pybind11::array_t<double> out({n, d});
    auto view = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < n; ++i) {
        view(i, 0) = set.x[i], view(i, 1) = set.y[i];
        if (d == 3) view(i, 2) = set.z[i];
    }
    return out;
}

ParticleSet load_particle_file(const std::string& path, const std::optional<std::vector<double>>& box,
                               const std::optional<std::string>& array, const std::optional<int>& dim,
                               const std::optional<double>& particle_radius)
{
    std::string box_text;
    if (box)
        for (double side : *box) box_text += (box_text.empty() ? "" : ",") + fmt::format("{}", side);
    if (box && box_text.empty()) box_text = ","; // an empty sequence: refused as a list without numbers
    const ParticleSource source =
        particle_source_of({path, "", box_text, array.value_or(""), "", 0, 1, 0, dim.value_or(0), particle_radius},
                           source_sources(FrontEnd::python));
    if (source.kind != SourceKind::file)
        fail_input(fmt::format("path: \"{}\" is a lattice or poisson source; expected a particle file", path));
    return load_source(source, source_sources(FrontEnd::python), 0);
}

} // namespace sphkern
