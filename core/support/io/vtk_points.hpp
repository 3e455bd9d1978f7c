// Legacy VTK output for particles (ParaView): the header, the points as vertices and the
// start of their point data. The caller adds its SCALARS and VECTORS after it.
#pragma once

#include "support/io/chunked_writer.hpp"

#include <cstddef>

namespace sphkern {

// `title` is the file's one-line title; x, y and z hold n coordinates each.
inline void write_vtk_points(ChunkedWriter& out, const char* title, std::size_t n, const double* x, const double* y,
                             const double* z)
{
    out.print("# vtk DataFile Version 3.0\n{}\nASCII\nDATASET POLYDATA\nPOINTS {} double\n", title, n);
    for (std::size_t i = 0; i < n; ++i) out.print("{:.17g} {:.17g} {:.17g}\n", x[i], y[i], z[i]);
    out.print("VERTICES {} {}\n", n, 2 * n);
    for (std::size_t i = 0; i < n; ++i) out.print("1 {}\n", i);
    out.print("POINT_DATA {}\n", n);
}

} // namespace sphkern
