// ParaView's own XML formats: an UnstructuredGrid (.vtu) of points, each its own vertex cell,
// with per-point arrays as raw binary appended data (doubles written as they are, read back
// bit for bit), and a collection (.pvd) that lists such files over time.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace sphkern {

// The points: one coordinate each per point; an empty z is 0 (2D).
struct VtuPoints {
    std::span<const double> x, y, z;
};

// One point array (PointData): `components` values a point (1, or 3 for a vector), value(i, c)
// the c-th of point i, for i in [0, n) and c in [0, components).
struct VtuArray {
    std::string name;
    int components = 1;
    std::function<double(std::size_t, int)> value;
};

// An UnstructuredGrid of points.x.size() points, one vertex cell each, the arrays as Float64
// point data, in the machine's byte order (header_type UInt64).
void write_vtu(std::ostream& out, const VtuPoints& points, const std::vector<VtuArray>& arrays);

// One member of a collection: its time and its file, relative to the .pvd's folder.
struct PvdEntry {
    double time = 0;
    std::string file;
};

// A ParaView collection (.pvd): one DataSet per entry, in the given order.
void write_pvd(std::ostream& out, const std::vector<PvdEntry>& entries);

// The k-th file of a series written beside `pvd` (NAME.pvd gives NAME_0000.vtu ...): the index
// is padded to the digits of `last`, the largest index, so the names sort in order.
std::filesystem::path pvd_member_path(const std::filesystem::path& pvd, std::size_t k, std::size_t last);

} // namespace sphkern
