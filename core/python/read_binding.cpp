// sphkern.read_particles: a particle file's arrays and header as sphkern's readers see them
// (the set `particles` and `assess` measure), for a user's own analysis or their own arrays.
#include "commands_binding.hpp"
#include "module_support.hpp"

#include "support/error.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

namespace py = pybind11;

namespace sphkern {

namespace {

py::object column(const ParticleValues& values)
{
    if (values.empty()) return py::none();
    return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::dict read_particles(const std::string& path, const std::optional<std::string>& array,
                        const std::optional<std::vector<double>>& box, const std::optional<int>& dim,
                        const std::optional<double>& particle_radius)
{
    ParticleSet set;
    {
        py::gil_scoped_release unlocked;
        set = load_particle_file(path, box, array, dim, particle_radius);
    }
    py::dict out;
    out["file"] = set.name;
    out["dimension"] = set.dimension;
    out["positions"] = positions_array(set);
    out["h"] = column(set.h);
    out["masses"] = column(set.mass);
    out["densities"] = column(set.density);
    if (set.box) {
        py::array_t<double> edges({set.dimension, set.dimension});
        auto view = edges.mutable_unchecked<2>();
        for (int a = 0; a < set.dimension; ++a)
            for (int b = 0; b < set.dimension; ++b) view(a, b) = set.box->edges(b, a); // row a: edge a
        out["box"] = edges;
    } else {
        out["box"] = py::none();
    }
    out["time"] = set.time ? py::object(py::float_(*set.time)) : py::none();
    out["support_per_h"] = set.support_per_h > 0 ? py::object(py::float_(set.support_per_h)) : py::none();
    out["kernel"] = set.file_kernel.empty() ? py::none() : py::object(py::str(set.file_kernel));
    out["neighbours_only"] = set.neighbours_only;
    py::list arrays;
    for (const auto& [name, first] : set.arrays) arrays.append(py::make_tuple(name, first));
    out["arrays"] = arrays;
    return out;
}

} // namespace

void bind_read_particles(py::module_& m)
{
    m.def("read_particles", &read_particles, py::arg("path"), py::kw_only(), py::arg("array") = py::none(),
          py::arg("box") = py::none(), py::arg("dim") = py::none(), py::arg("particle_radius") = py::none(),
          R"doc(A particle file as sphkern reads it.

Parameters
----------
path : str
    A SWIFT, GADGET or PySPH HDF5 file, a GADGET-2 binary snapshot, a Phantom dump, CSV or VTK.
array : str, optional
    PySPH's particle array, or several ("fluid,solid": the first measured, all neighbours).
box : sequence of float, optional
    A periodic box [Lx, Ly(, Lz)] from the origin, for a file that has none.
dim : int, optional
    2: a 3-column set with one constant coordinate is read as 2D.
particle_radius : float, optional
    SPlisHSPlasH's particle radius (its VTK files hold none).

Returns
-------
dict
    ``file``, ``dimension``, ``positions`` (N, D), ``h``, ``masses`` and ``densities`` (arrays,
    or None where the file has none), ``box`` (D x D, a row per edge, or None), ``time`` (the
    header's, or None), ``support_per_h`` (the file's convention, or None), ``kernel`` (as the
    file names it, or None), ``neighbours_only`` and ``arrays`` (PySPH: each array's name and
    first row). The values are those `particles` and `assess` measure, wrapped into the box.

Examples
--------
>>> import os, tempfile, sphkern
>>> path = os.path.join(tempfile.mkdtemp(), "two.csv")
>>> _ = open(path, "w").write("x,y\n0.25,0.5\n0.75,0.5\n")
>>> sphkern.read_particles(path, box=[1, 1])["positions"].shape
(2, 2)
)doc");
}

} // namespace sphkern
