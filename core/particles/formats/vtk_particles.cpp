// Legacy VTK files (before format 5's OFFSETS/CONNECTIVITY): POLYDATA or UNSTRUCTURED_GRID,
// ASCII or BINARY (big-endian), POINTS and the POINT_DATA arrays named as in
// column_names.cpp (SCALARS, VECTORS, NORMALS, FIELD). Cells and CELL_DATA are skipped.
#include "particles/formats/column_names.hpp"
#include "particles/formats/particle_files.hpp"

#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/io/json_input.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <map>
#include <string_view>

namespace sphkern {

namespace {

class VtkCursor {
public:
    VtkCursor(std::string_view data, std::string name) : data_(data), name_(std::move(name)) {}
    bool binary = false;

    [[noreturn]] void fail(const std::string& what) const
    {
        fail_input(fmt::format("{}: line {}: {}", name_, line_, what));
    }
    bool at_end()
    {
        skip_space();
        return pos_ >= data_.size();
    }
    std::string_view line()
    {
        if (pos_ >= data_.size()) fail("unexpected end of file");
        const std::size_t end = data_.find('\n', pos_);
        std::string_view text = data_.substr(pos_, end == std::string_view::npos ? std::string_view::npos : end - pos_);
        pos_ = end == std::string_view::npos ? data_.size() : end + 1;
        ++line_;
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        return text;
    }
    std::string_view token()
    {
        skip_space();
        if (pos_ >= data_.size()) fail("unexpected end of file");
        const std::size_t start = pos_;
        while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
        return data_.substr(start, pos_ - start);
    }
    std::size_t count(const char* what)
    {
        const auto text = token();
        std::size_t n = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
        if (error != std::errc() || end != text.data() + text.size() || n > (std::size_t{1} << 40))
            fail(fmt::format("{}: \"{}\" is not a count", what, text));
        return n;
    }
    // `n` numbers of VTK type `type`, as doubles (or skipped when `out` is null).
    void values(std::string_view type, std::size_t n, std::vector<double>* out, const std::string& what)
    {
        if (!binary) {
            // A declared count is believed only as far as the file can hold it (a number and a space each).
            if (out) out->reserve(std::min(n, (data_.size() - pos_ + 1) / 2));
            for (std::size_t i = 0; i < n; ++i) {
                const auto text = token();
                double v = 0;
                const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
                if (error != std::errc() || end != text.data() + text.size())
                    fail(fmt::format("{}, value {}: \"{}\" is not a number", what, i, text));
                if (out) out->push_back(v);
            }
            return;
        }
        // Binary data starts after the end of the keyword's line.
        if (pos_ > 0 && data_[pos_ - 1] != '\n') {
            const std::size_t end = data_.find('\n', pos_);
            pos_ = end == std::string_view::npos ? data_.size() : end + 1;
        }
        const std::size_t size = type_size(type, what);
        if (n > (data_.size() - pos_) / size) fail(fmt::format("{}: the file ends inside its {} values", what, n));
        if (out) out->reserve(n);
        if (out)
            for (std::size_t i = 0; i < n; ++i) out->push_back(big_endian(type, data_.data() + pos_ + i * size));
        pos_ += n * size;
    }

private:
    void skip_space()
    {
        while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) {
            if (data_[pos_] == '\n') ++line_;
            ++pos_;
        }
    }
    std::size_t type_size(std::string_view type, const std::string& what) const
    {
        if (type == "double" || type == "long" || type == "unsigned_long" || type == "vtktypeint64" ||
            type == "vtktypeuint64")
            return 8;
        if (type == "float" || type == "int" || type == "unsigned_int" || type == "vtkIdType" || type == "vtktypeint32")
            return 4;
        if (type == "short" || type == "unsigned_short") return 2;
        if (type == "char" || type == "unsigned_char" || type == "bit") return 1;
        fail(fmt::format("{}: unknown data type \"{}\"", what, type));
    }
    static double big_endian(std::string_view type, const char* p)
    {
        auto load = [p](auto value) {
            std::memcpy(&value, p, sizeof value);
            if constexpr (std::endian::native == std::endian::little) value = byteswap(value);
            return value;
        };
        if (type == "double") return std::bit_cast<double>(load(std::uint64_t{}));
        if (type == "float") return std::bit_cast<float>(load(std::uint32_t{}));
        if (type == "long" || type == "vtktypeint64")
            return static_cast<double>(static_cast<std::int64_t>(load(std::uint64_t{})));
        if (type == "unsigned_long" || type == "vtktypeuint64") return static_cast<double>(load(std::uint64_t{}));
        if (type == "unsigned_int") return load(std::uint32_t{});
        if (type == "int" || type == "vtkIdType" || type == "vtktypeint32")
            return static_cast<std::int32_t>(load(std::uint32_t{}));
        if (type == "short") return static_cast<std::int16_t>(load(std::uint16_t{}));
        if (type == "unsigned_short") return load(std::uint16_t{});
        if (type == "char") return static_cast<signed char>(*p);
        return static_cast<unsigned char>(*p);
    }
    template <class T>
    static T byteswap(T v)
    {
        if constexpr (sizeof(T) == 8) return __builtin_bswap64(v);
        else if constexpr (sizeof(T) == 4) return __builtin_bswap32(v);
        else return __builtin_bswap16(v);
    }

    std::string_view data_;
    std::string name_;
    std::size_t pos_ = 0, line_ = 0;
};

// "# vtk DataFile Version", the title (returned), the encoding and an ASCII or BINARY point dataset.
std::string read_vtk_header(VtkCursor& in)
{
    if (in.line().rfind("# vtk DataFile", 0) != 0)
        in.fail("not a legacy VTK file; expected \"# vtk DataFile Version\"");
    std::string title(in.line());
    const auto encoding = in.token();
    if (encoding != "ASCII" && encoding != "BINARY") in.fail(fmt::format("\"{}\": expected ASCII or BINARY", encoding));
    in.binary = encoding == "BINARY";
    if (in.token() != "DATASET") in.fail("expected DATASET");
    const auto dataset = in.token();
    if (dataset != "POLYDATA" && dataset != "UNSTRUCTURED_GRID")
        in.fail(fmt::format("DATASET {}: expected POLYDATA or UNSTRUCTURED_GRID (particles as points)", dataset));
    return title;
}

// The sections after the header: the points and the point arrays with a particle field's
// name; cells, cell data and metadata are read past.
class VtkSections {
public:
    explicit VtkSections(VtkCursor& in) : in_(in) {}
    void read_all()
    {
        while (!in_.at_end()) read_section(std::string(in_.token()));
    }

    std::vector<double> points; // x, y, z of each point
    std::size_t count = 0;
    std::map<ParticleField, ParticleValues> arrays;

private:
    void read_section(const std::string& keyword)
    {
        if (keyword == "POINTS") {
            count = in_.count("POINTS");
            in_.values(in_.token(), 3 * count, &points, "POINTS");
        } else if (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" ||
                   keyword == "TRIANGLE_STRIPS" || keyword == "CELLS") {
            in_.count(keyword.c_str());
            in_.values("int", in_.count(keyword.c_str()), nullptr, keyword);
        } else if (keyword == "CELL_TYPES") {
            in_.values("int", in_.count("CELL_TYPES"), nullptr, keyword);
        } else if (keyword == "POINT_DATA" || keyword == "CELL_DATA") {
            const std::size_t n = in_.count(keyword.c_str());
            point_data_ = keyword == "POINT_DATA";
            if (point_data_ && n != count) in_.fail(fmt::format("POINT_DATA {}: expected {} as in POINTS", n, count));
        } else if (keyword == "SCALARS") {
            read_scalars();
        } else if (keyword == "VECTORS" || keyword == "NORMALS") {
            const std::string array(in_.token());
            read_array(array, in_.token(), 3, point_data_ ? count : 0);
        } else if (keyword == "FIELD") {
            read_field();
        } else if (keyword == "METADATA") {
            while (!in_.at_end() && !in_.line().empty()) {}
        } else {
            in_.fail(fmt::format("unknown section \"{}\"", keyword));
        }
    }
    // SCALARS name type [components] LOOKUP_TABLE table, then the values.
    void read_scalars()
    {
        const std::string array(in_.token());
        const auto type = in_.token();
        std::size_t components = 1;
        std::string next(in_.token());
        if (next != "LOOKUP_TABLE") {
            std::from_chars(next.data(), next.data() + next.size(), components);
            next = in_.token();
        }
        if (next != "LOOKUP_TABLE") in_.fail("SCALARS " + array + ": expected LOOKUP_TABLE");
        in_.token(); // the table's name
        read_array(array, type, components, point_data_ ? count : 0);
    }
    // FIELD name n, then n arrays: name components tuples type, then the values.
    void read_field()
    {
        in_.token(); // the field's name
        const std::size_t n = in_.count("FIELD");
        for (std::size_t a = 0; a < n; ++a) {
            const std::string array(in_.token());
            const std::size_t components = in_.count(array.c_str()), tuples = in_.count(array.c_str());
            read_array(array, in_.token(), components, tuples);
        }
    }
    // Kept when it is point data of one component named as a particle field other than a
    // coordinate; read past otherwise.
    void read_array(const std::string& array, std::string_view type, std::size_t components, std::size_t tuples)
    {
        const auto field = point_data_ && components == 1 ? particle_field(array) : std::nullopt;
        std::vector<double> values;
        in_.values(type, components * tuples, field ? &values : nullptr, "array " + array);
        if (field && field != ParticleField::x && field != ParticleField::y && field != ParticleField::z)
            arrays[*field] = ParticleValues(values.begin(), values.end());
    }

    VtkCursor& in_;
    bool point_data_ = false;
};

// The particle set of the points and arrays read; a set whose z is constant is 2D.
ParticleSet vtk_particle_set(const std::string& name, VtkSections& sections)
{
    const std::size_t count = sections.count;
    ParticleSet set;
    set.name = name;
    set.dimension = 3;
    for (std::size_t i = 0; i < count; ++i) {
        const double* p = sections.points.data() + 3 * i;
        set.x.push_back(p[0]), set.y.push_back(p[1]), set.z.push_back(p[2]);
    }
    for (auto& [field, values] : sections.arrays) {
        if (values.size() != count)
            fail_input(
                fmt::format("{}: array {} has {} values for {} points", name, field_name(field), values.size(), count));
        (field == ParticleField::h ? set.h : field == ParticleField::mass ? set.mass : set.density) = std::move(values);
    }
    // VTK points are always 3D.
    if (std::all_of(set.z.begin(), set.z.end(), [&](double z) { return z == set.z[0]; })) {
        set.dimension = 2;
        set.gravity = Eigen::Vector3d(0, -1, 0);
        std::fill(set.z.begin(), set.z.end(), 0.0);
    }
    return set;
}

// SPlisHSPlasH's exporter (ParticleExporter_VTK) gives its files this title. It writes no h:
// its support is 4 particle radii (Simulation::setParticleRadius), the radius a scene
// parameter the file does not hold, so it comes from the options or not at all.
void apply_particle_radius(ParticleSet& set, const std::string& title, const ParticleFileOptions& options)
{
    const bool splishsplash = title == "SPlisHSPlasH particle data";
    if (options.particle_radius && !splishsplash)
        throw Error(ExitCode::usage,
                    fmt::format("{}: {} is not SPlisHSPlasH's (its title is not "
                                "\"SPlisHSPlasH particle data\"); the radius gives the h of its files only",
                                setting_named("particle_radius"), set.name));
    if (!splishsplash || !set.h.empty()) return;
    if (!options.particle_radius) {
        set.support_per_radius = 4;
        return;
    }
    set.h.assign(set.size(), *options.particle_radius);
    set.support_per_h = 4;
}

} // namespace

ParticleSet read_vtk_particles(const std::filesystem::path& file, const ParticleFileOptions& options)
{
    const std::string name = file.string();
    const std::string text = read_input_file(file, particle_file_byte_limit(), "a VTK particle file");
    VtkCursor in(text, name);
    const std::string title = read_vtk_header(in);
    VtkSections sections(in);
    sections.read_all();
    if (sections.points.empty()) in.fail("no POINTS");
    ParticleSet set = vtk_particle_set(name, sections);
    apply_particle_radius(set, title, options);
    return set;
}

} // namespace sphkern
