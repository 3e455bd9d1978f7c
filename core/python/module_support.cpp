#include "module_support.hpp"

#include "support/error.hpp"

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

} // namespace sphkern
