// The module's exceptions, by kind: sphkern.Error and its subclasses, each also a subclass of
// the built-in exception a Python user catches for that kind (ValueError, LookupError,
// FileNotFoundError, RuntimeError, OSError), and the translation of sphkern's Error into them.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace sphkern {

// Defines the classes on the module and translates every Error from then on.
void bind_errors(pybind11::module_& m);

// Raises sphkern.CheckFailed with `message`, the checks' documents on its `results`.
[[noreturn]] void raise_check_failed(const std::string& message, const pybind11::object& results);

} // namespace sphkern
