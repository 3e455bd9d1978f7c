// Legacy VTK output for particles (ParaView): the header, the points as vertices and the
// start of their point data. The caller adds its SCALARS and VECTORS after it.
#pragma once

#include "support/io/chunked_writer.hpp"

#include <cstddef>

namespace sphkern {

// `title` is the file's one-line title; x, y and z hold n coordinates each, written in the
// shortest form that reads back to the same double, formatted on `threads` threads.
inline void write_vtk_points(ChunkedWriter& out, const char* title, std::size_t n, const double* x, const double* y,
                             const double* z, int threads)
{
    out.print("# vtk DataFile Version 3.0\n{}\nASCII\nDATASET POLYDATA\nPOINTS {} double\n", title, n);
    out.rows(n, threads, [&](fmt::memory_buffer& row, std::size_t i) {
        fmt::format_to(std::back_inserter(row), "{} {} {}\n", x[i], y[i], z[i]);
    });
    out.print("VERTICES {} {}\n", n, 2 * n);
    out.rows(n, threads,
             [](fmt::memory_buffer& row, std::size_t i) { fmt::format_to(std::back_inserter(row), "1 {}\n", i); });
    out.print("POINT_DATA {}\n", n);
}

} // namespace sphkern
