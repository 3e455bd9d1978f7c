// numpy arrays in and out of the module: real numbers only (numpy would drop the imaginary
// part of a complex value without a word), C order, converted once.
#pragma once

#include "support/error.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace sphkern {

using DoubleArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

inline DoubleArray real_array(const pybind11::object& values, const std::string& what, const std::string& expected)
{
    if (pybind11::module_::import("numpy").attr("iscomplexobj")(values).cast<bool>())
        fail_input(what + ": complex numbers; expected real numbers");
    try {
        return values.cast<DoubleArray>();
    } catch (const pybind11::cast_error&) {
        fail_input(what + ": expected " + expected);
    } catch (const pybind11::error_already_set& e) { // numpy's own refusal, as of a text
        if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError)) throw;
        fail_input(what + ": expected " + expected);
    }
}

} // namespace sphkern
