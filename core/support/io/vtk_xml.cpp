#include "support/io/vtk_xml.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>

namespace sphkern {

namespace {

// The bytes are the machine's own, so the header says which order they are in.
constexpr const char* native_byte_order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

// A name or file inside an attribute's quotes.
std::string xml_attribute(const std::string& text)
{
    std::string escaped;
    for (char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

template <class T>
void write_raw(std::ostream& out, const T* data, std::size_t count)
{
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
}

// One appended block: its length in bytes (the UInt64 header), then count values of T, made
// by value(k) for k in [0, count) a buffer at a time, so that no copy of a whole array is held.
template <class T, class Value>
void write_block(std::ostream& out, std::size_t count, const Value& value)
{
    const std::uint64_t bytes = count * sizeof(T);
    write_raw(out, &bytes, 1);
    std::vector<T> buffer(std::min<std::size_t>(count, 1u << 15));
    for (std::size_t first = 0; first < count; first += buffer.size()) {
        const std::size_t n = std::min(buffer.size(), count - first);
        for (std::size_t k = 0; k < n; ++k) buffer[k] = value(first + k);
        write_raw(out, buffer.data(), n);
    }
}

} // namespace

void write_vtu(std::ostream& out, const VtuPoints& points, const std::vector<VtuArray>& arrays)
{
    const std::size_t n = points.x.size();
    if (points.y.size() != n || (!points.z.empty() && points.z.size() != n))
        throw std::invalid_argument("write_vtu: x, y and z hold different numbers of points");
    for (const auto& a : arrays)
        if (a.components < 1 || !a.value) throw std::invalid_argument("write_vtu: array " + a.name + " has no values");
    // Each block's offset counts from the first byte after '_': its header and its values.
    std::uint64_t offset = 0;
    auto next = [&](std::size_t bytes) {
        const std::uint64_t at = offset;
        offset += sizeof(std::uint64_t) + bytes;
        return at;
    };
    out << "<?xml version=\"1.0\"?>\n"
        << fmt::format("<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"{}\" header_type=\"UInt64\">\n",
                       native_byte_order)
        << "  <UnstructuredGrid>\n"
        << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, n) << "      <PointData>\n";
    for (const auto& a : arrays)
        out << fmt::format(
            "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
            "offset=\"{}\"/>\n",
            xml_attribute(a.name), a.components, next(n * a.components * sizeof(double)));
    out << "      </PointData>\n      <Points>\n"
        << fmt::format(
               "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"{}\"/>\n",
               next(n * 3 * sizeof(double)))
        << "      </Points>\n      <Cells>\n"
        << fmt::format("        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"{}\"/>\n",
                       next(n * sizeof(std::int64_t)))
        << fmt::format("        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"{}\"/>\n",
                       next(n * sizeof(std::int64_t)))
        << fmt::format("        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"{}\"/>\n",
                       next(n * sizeof(std::uint8_t)))
        << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
    for (const auto& a : arrays) {
        const auto c = static_cast<std::size_t>(a.components);
        write_block<double>(out, n * c, [&](std::size_t k) { return a.value(k / c, static_cast<int>(k % c)); });
    }
    write_block<double>(out, 3 * n, [&](std::size_t k) {
        const std::size_t i = k / 3;
        switch (k % 3) {
        case 0: return points.x[i];
        case 1: return points.y[i];
        default: return points.z.empty() ? 0.0 : points.z[i];
        }
    });
    // Point i is cell i, a vertex (VTK type 1) whose one point ends at offset i + 1.
    write_block<std::int64_t>(out, n, [](std::size_t i) { return static_cast<std::int64_t>(i); });
    write_block<std::int64_t>(out, n, [](std::size_t i) { return static_cast<std::int64_t>(i + 1); });
    write_block<std::uint8_t>(out, n, [](std::size_t) { return std::uint8_t{1}; });
    out << "\n  </AppendedData>\n</VTKFile>\n";
}

void write_pvd(std::ostream& out, const std::vector<PvdEntry>& entries)
{
    out << "<?xml version=\"1.0\"?>\n"
        << fmt::format("<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"{}\">\n", native_byte_order)
        << "  <Collection>\n";
    for (const auto& e : entries)
        out << fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.time,
                           xml_attribute(e.file));
    out << "  </Collection>\n</VTKFile>\n";
}

std::filesystem::path pvd_member_path(const std::filesystem::path& pvd, std::size_t k, std::size_t last)
{
    const std::size_t width = fmt::formatted_size("{}", std::max(k, last));
    return pvd.parent_path() / fmt::format("{}_{:0{}}.vtu", pvd.stem().string(), k, width);
}

} // namespace sphkern
