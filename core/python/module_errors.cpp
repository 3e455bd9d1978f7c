#include "module_errors.hpp"

#include "requests/settings/command_settings.hpp"
#include "support/error.hpp"

namespace py = pybind11;

namespace sphkern {

namespace {

// The classes, made once when the module is imported and kept for the process's life.
struct ErrorClasses {
    PyObject* error = nullptr;     // Error(Exception): the base of them all
    PyObject* bad_value = nullptr; // BadValue(Error, ValueError): a value out of range, of the wrong kind, not fitting
    PyObject* unknown_name =
        nullptr; // UnknownName(BadValue, LookupError): a kernel, lattice, study, code ... that is not known
    PyObject* file_error = nullptr; // FileError(BadValue, FileNotFoundError): an input file that is not there
    PyObject* plugin_error =
        nullptr; // PluginError(Error, RuntimeError): a plugin that cannot be loaded, validated or run
    PyObject* output_error = nullptr; // OutputError(Error, OSError): results that cannot be written, or exist
    PyObject* check_failed = nullptr; // CheckFailed(Error): a kernel check failed (check)
};

ErrorClasses& classes()
{
    static ErrorClasses c;
    return c;
}

PyObject* make_class(py::module_& m, const char* name, std::initializer_list<PyObject*> bases, const char* doc)
{
    py::tuple base_tuple(bases.size());
    std::size_t i = 0;
    for (PyObject* base : bases) base_tuple[i++] = py::reinterpret_borrow<py::object>(base);
    py::dict body;
    body["__doc__"] = doc;
    body["__module__"] = "sphkern";
    py::object cls =
        py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyType_Type))(name, base_tuple, body);
    m.attr(name) = cls;
    return cls.release().ptr(); // kept: the translator uses it for the process's life
}

PyObject* class_of(const Error& e)
{
    const auto& c = classes();
    if (e.kind() == ErrorKind::missing_file) return c.file_error;
    if (e.kind() == ErrorKind::unknown_name) return c.unknown_name;
    switch (e.code()) {
    case ExitCode::plugin: return c.plugin_error;
    case ExitCode::output: return c.output_error;
    case ExitCode::check_failed: return c.check_failed;
    default: return c.bad_value;
    }
}

// An instance of `cls` with the message and the command line's exit code for the same error.
void set_python_error(PyObject* cls, const std::string& message, ExitCode code)
{
    py::object error = py::reinterpret_borrow<py::object>(cls)(message);
    error.attr("exit_code") = static_cast<int>(code);
    PyErr_SetObject(cls, error.ptr());
}

} // namespace

void bind_errors(py::module_& m)
{
    auto& c = classes();
    c.error = make_class(m, "Error", {PyExc_Exception},
                         "The base of every error sphkern raises; exit_code is the command line's for the same error.");
    c.bad_value = make_class(m, "BadValue", {c.error, PyExc_ValueError},
                             "A value out of its range, of the wrong kind, or not fitting the others given.");
    c.unknown_name = make_class(m, "UnknownName", {c.bad_value, PyExc_LookupError},
                                "A name that names nothing known: a kernel, lattice, study, code, parameter or a_p.");
    c.file_error = make_class(m, "FileError", {c.bad_value, PyExc_FileNotFoundError},
                              "An input file that is not there (a lattice, study, particle or plugin file).");
    c.plugin_error = make_class(m, "PluginError", {c.error, PyExc_RuntimeError},
                                "A plugin that cannot be loaded, validated or run.");
    c.output_error = make_class(m, "OutputError", {c.error, PyExc_OSError},
                                "Results that cannot be written, or an output that exists (force replaces it).");
    c.check_failed = make_class(m, "CheckFailed", {c.error},
                                "A kernel check failed, or warned with strict; the checks' documents are on results.");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const Error& e) {
            const std::string message = one_line(spelled_message(FrontEnd::python, e.what()));
            if (e.code() == ExitCode::interrupted) PyErr_SetString(PyExc_KeyboardInterrupt, message.c_str());
            else set_python_error(class_of(e), message, e.code());
        }
    });
}

void raise_check_failed(const std::string& message, const py::object& results)
{
    PyObject* cls = classes().check_failed;
    py::object error = py::reinterpret_borrow<py::object>(cls)(message);
    error.attr("exit_code") = static_cast<int>(ExitCode::check_failed);
    error.attr("results") = results;
    PyErr_SetObject(cls, error.ptr());
    throw py::error_already_set();
}

} // namespace sphkern
