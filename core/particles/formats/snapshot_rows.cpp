#include "particles/formats/snapshot_rows.hpp"

#include "codes/swift/swift_kernels.hpp"
#include "particles/formats/hdf5_file.hpp"

#include <cmath>
#include <optional>
#include <regex>

namespace sphkern {

namespace snapshot_detail {

// One file of a snapshot as its header declares it: the set without particles, its rows, and
// the datasets it holds.
struct SnapshotPart {
    ParticleSet header;
    std::size_t rows = 0, columns = 3;
    std::string h, mass, density; // the datasets' paths, empty where the file has none
    double table_mass = 0;        // MassTable[0], every particle's mass where there is no dataset
};

} // namespace snapshot_detail

namespace {

using namespace hdf5;
using snapshot_detail::SnapshotPart;

const std::string coordinates_path = "/PartType0/Coordinates";

// GADGET-4 writes /Header, /Parameters and /Config (its compile-time options) beside its
// particle groups; SWIFT writes no /Config, and /Code, /HydroScheme, /Units and /Header "Code"
// = "SWIFT", none of which GADGET-4 writes. Initial conditions with neither mark stay unknown.
bool written_by_gadget(const File& f)
{
    if (!f.exists("/Config") || !f.exists("/Parameters")) return false;
    for (const char* swift : {"/Code", "/HydroScheme", "/Units"})
        if (f.exists(swift)) return false;
    return f.text_attribute("/Header", "Code").empty();
}

SnapshotPart snapshot_part(const File& f)
{
    SnapshotPart part;
    ParticleSet& set = part.header;
    set.name = f.name;
    if (!f.exists(coordinates_path))
        fail_input(f.name + ": /PartType0/Coordinates is missing; expected a SWIFT or GADGET snapshot");
    const auto dimension = f.attribute("/Header", "Dimension");
    if (!dimension.empty() && dimension[0] != 2 && dimension[0] != 3)
        fail_input(fmt::format("{}: /Header Dimension is {}; expected 2 or 3", f.name, dimension[0]));
    set.dimension = dimension.empty() ? 3 : static_cast<int>(dimension[0]);
    const auto shape = f.shape(coordinates_path);
    if (shape.size() != 2 || (shape[1] != 3 && shape[1] != static_cast<hsize_t>(set.dimension)))
        fail_input(
            fmt::format("{}: /PartType0/Coordinates has shape {}; expected (N, 3)", f.name, File::shape_text(shape)));
    const std::size_t n = static_cast<std::size_t>(shape[0]);
    part.rows = n, part.columns = static_cast<std::size_t>(shape[1]);
    const auto this_file = f.attribute("/Header", "NumPart_ThisFile");
    if (!this_file.empty() && static_cast<std::size_t>(this_file[0]) != n)
        fail_input(fmt::format(
            "{}: /Header NumPart_ThisFile[0] is {} but /PartType0/Coordinates has {} rows; expected the two equal",
            f.name, this_file[0], n));
    if (set.dimension == 2) set.gravity = Eigen::Vector3d(0, -1, 0);
    // A column's dataset under any of its names, checked to hold one number per particle.
    auto column = [&](std::initializer_list<const char*> names) -> std::string {
        for (const char* dataset : names) {
            const std::string path = std::string("/PartType0/") + dataset;
            if (!f.exists(path)) continue;
            // SWIFT's own example scripts write (N, 1), which SWIFT reads as (N).
            if (const auto s = f.shape(path); !(s.size() == 1 || (s.size() == 2 && s[1] == 1)) || s[0] != n)
                fail_input(fmt::format("{}: dataset {} has shape {}; expected ({}) or ({}, 1)", f.name, path,
                                       File::shape_text(s), n, n));
            return path;
        }
        return {};
    };
    part.h = column({"SmoothingLengths", "SmoothingLength"});
    part.mass = column({"Masses", "Mass"});
    part.density = column({"Densities", "Density"});
    const auto table = f.attribute("/Header", "MassTable");
    if (part.mass.empty() && !table.empty() && table[0] > 0) part.table_mass = table[0];
    const auto box = f.attribute("/Header", "BoxSize");
    if (!box.empty()) {
        PeriodicBox b;
        for (int a = 0; a < 3; ++a) b.edges(a, a) = box.size() >= 3 ? box[static_cast<std::size_t>(a)] : box[0];
        if (set.dimension == 2) b.edges(2, 2) = 1;
        set.box = b;
    }
    if (const auto time = f.attribute("/Header", "Time"); !time.empty()) set.time = time[0];
    const auto gamma = f.attribute("/HydroScheme", "Kernel gamma");
    if (!gamma.empty()) set.support_per_h = gamma[0];
    // GADGET's SmoothingLength is the radius where its kernel reaches zero.
    if (written_by_gadget(f)) set.support_per_h = 1;
    set.file_kernel = f.text_attribute("/HydroScheme", "Kernel function");
    set.file_kernel_name = sphkern_kernel_of_swift(set.file_kernel);
    return part;
}

// Rows [begin, end) of one file appended to `set`.
void append_rows(const File& f, const SnapshotPart& part, std::size_t begin, std::size_t end, ParticleSet& set)
{
    const std::size_t count = end - begin, columns = part.columns;
    const auto coordinates = f.row_range(coordinates_path, begin, count, columns);
    const std::size_t at = set.x.size();
    set.x.resize(at + count), set.y.resize(at + count), set.z.resize(at + count);
    for (std::size_t i = 0; i < count; ++i) {
        set.x[at + i] = coordinates[i * columns];
        set.y[at + i] = coordinates[i * columns + 1];
        set.z[at + i] = set.dimension == 3 ? coordinates[i * columns + 2] : 0.0;
    }
    auto append = [&](const std::string& path, ParticleValues& into) {
        if (path.empty()) return;
        const auto values = f.row_range(path, begin, count, 1);
        into.insert(into.end(), values.begin(), values.end());
    };
    append(part.h, set.h), append(part.mass, set.mass), append(part.density, set.density);
    if (part.mass.empty() && part.table_mass > 0) set.mass.resize(at + count, part.table_mass);
}

// The gas particles a snapshot's header declares in all its files (NumPart_Total and its high word),
// none where it has no NumPart_Total.
std::optional<double> declared_total(const File& f)
{
    const auto low = f.attribute("/Header", "NumPart_Total"), high = f.attribute("/Header", "NumPart_Total_HighWord");
    if (low.empty()) return std::nullopt;
    return low[0] + (high.empty() ? 0.0 : high[0] * 4294967296.0);
}

// A file's name as a part of a snapshot, BASE.K.hdf5 (or .h5); none if it has no such name.
struct PartName {
    std::string base, extension;
    std::size_t k = 0;
    std::filesystem::path of(std::size_t part) const { return fmt::format("{}.{}.{}", base, part, extension); }
};

std::optional<PartName> part_name(const std::filesystem::path& file)
{
    static const std::regex part(R"((.*)\.(\d{1,9})\.(hdf5|h5))");
    std::smatch m;
    const std::string name = file.string();
    if (!std::regex_match(name, m, part)) return std::nullopt;
    return PartName{m[1].str(), m[3].str(), static_cast<std::size_t>(std::stoul(m[2].str()))};
}

// Every part's header must be the first's: the parts of one snapshot.
void check_same_header(const File& first, const File& part)
{
    for (const char* attr :
         {"NumFilesPerSnapshot", "NumPart_Total", "NumPart_Total_HighWord", "BoxSize", "MassTable", "Dimension"})
        if (part.attribute("/Header", attr) != first.attribute("/Header", attr))
            fail_input(fmt::format("{}: /Header {} differs from {}'s; expected the parts of one snapshot", part.name,
                                   attr, first.name));
}

// Every part must hold what the first holds.
void check_same_columns(const SnapshotPart& first, const SnapshotPart& part)
{
    const std::pair<const std::string*, const std::string*> columns[] = {{&first.h, &part.h},
                                                                         {&first.mass, &part.mass},
                                                                         {&first.density, &part.density}};
    for (const auto& [mine, theirs] : columns)
        if (mine->empty() != theirs->empty())
            fail_input(
                fmt::format("{}: its smoothing lengths, masses or densities are {} where the first part's are {}; "
                            "expected the parts of one snapshot",
                            part.header.name, theirs->empty() ? "missing" : "present",
                            mine->empty() ? "missing" : "present"));
}

} // namespace

struct SnapshotRows::Parts {
    struct Part {
        std::filesystem::path path;
        std::size_t first = 0; // its first row among all parts'
        snapshot_detail::SnapshotPart layout;
    };
    std::vector<Part> list;
    std::size_t total = 0;
    std::string name; // the file as named
    ParticleSet sample;
    // The part read last, kept open: a run of rows is read from one or two parts.
    mutable std::unique_ptr<OpenFile> open;
    mutable std::size_t open_index = 0;

    const File& file(std::size_t k) const
    {
        if (!open || open_index != k) open.reset(), open = std::make_unique<OpenFile>(list[k].path), open_index = k;
        return open->file();
    }
};

SnapshotRows::SnapshotRows(const std::filesystem::path& file) : parts_(std::make_unique<Parts>())
{
    silence_hdf5();
    auto& parts = *parts_;
    parts.name = file.string();
    std::vector<std::string> inputs;
    const auto named = std::make_unique<OpenFile>(file);
    const File& f = named->file();
    const auto files = f.attribute("/Header", "NumFilesPerSnapshot");
    const auto total = declared_total(f);
    const auto name = part_name(f.name);
    // A file not named as a part that holds the declared rows is the whole snapshot (SWIFT's
    // virtual file over its parts, or the parts joined), whatever NumFilesPerSnapshot says.
    const bool whole =
        files.empty() || files[0] <= 1 ||
        (!name && f.exists(coordinates_path) && static_cast<double>(f.rows(coordinates_path)) >= total.value_or(0.0));
    if (whole) {
        parts.list.push_back({file, 0, snapshot_part(f)});
        const std::size_t rows = parts.list.back().layout.rows;
        if (total && static_cast<double>(rows) != *total)
            fail_input(fmt::format("{}: /Header NumPart_Total declares {:.0f} particles but "
                                   "/PartType0/Coordinates has {} rows; expected the file's own rows",
                                   f.name, *total, rows));
    } else {
        const auto count = static_cast<std::size_t>(files[0]);
        if (files[0] != std::floor(files[0]) || files[0] > 1e5)
            fail_input(fmt::format("{}: /Header NumFilesPerSnapshot is {}; expected a whole number of files", f.name,
                                   files[0]));
        if (!name)
            fail_input(fmt::format(
                "{}: one of {} files of a snapshot (/Header NumFilesPerSnapshot), but not named BASE.K.hdf5; "
                "expected the parts' own names",
                f.name, count));
        // A file beside the parts, its header copied from theirs, would otherwise read as them.
        if (name->k >= count)
            fail_input(fmt::format(
                "{}: part {} of a snapshot whose header says {} files (/Header NumFilesPerSnapshot), parts 0 "
                "to {}; expected one of those",
                f.name, name->k, count, count - 1));
        // Every part is opened and checked, whichever was named: each holds the rows its
        // NumPart_ThisFile says, and together they hold NumPart_Total.
        std::size_t first = 0;
        for (std::size_t k = 0; k < count; ++k) {
            const std::filesystem::path path = name->of(k);
            std::error_code ec;
            if (!std::filesystem::is_regular_file(path, ec))
                fail_input(fmt::format("{}: part {} of the snapshot's {} files, {}, {}; expected every part", f.name, k,
                                       count, path.string(),
                                       std::filesystem::is_directory(path, ec) ? "is a folder" : "does not exist"));
            const OpenFile part(path);
            check_same_header(f, part.file());
            SnapshotPart layout = snapshot_part(part.file());
            if (k > 0) check_same_columns(parts.list.front().layout, layout);
            first += layout.rows;
            parts.list.push_back({path, first - layout.rows, std::move(layout)});
            inputs.push_back(path.lexically_normal().string());
            inputs.insert(inputs.end(), part.linked_files().begin(), part.linked_files().end());
        }
        if (total && static_cast<double>(first) != *total)
            fail_input(
                fmt::format("{}: the snapshot's {} files hold {} particles but /Header NumPart_Total declares {:.0f}; "
                            "expected the parts of one snapshot",
                            f.name, count, first, *total));
    }
    inputs.insert(inputs.end(), named->linked_files().begin(), named->linked_files().end());
    parts.total = parts.list.back().first + parts.list.back().layout.rows;
    std::sort(inputs.begin(), inputs.end());
    inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
    parts.sample = rows(0, std::min<std::size_t>(parts.total, 2));
    parts.sample.linked_files = std::move(inputs);
}

SnapshotRows::~SnapshotRows() = default;

std::size_t SnapshotRows::size() const { return parts_->total; }

std::size_t SnapshotRows::parts() const { return parts_->list.size(); }

const ParticleSet& SnapshotRows::sample() const { return parts_->sample; }

ParticleSet SnapshotRows::rows(std::size_t begin, std::size_t end) const
{
    const auto& parts = *parts_;
    ParticleSet set = parts.list.front().layout.header;
    set.name = parts.name;
    if (end > begin) {
        set.x.reserve(end - begin), set.y.reserve(end - begin), set.z.reserve(end - begin);
        for (std::size_t k = 0; k < parts.list.size(); ++k) {
            const auto& part = parts.list[k];
            const std::size_t from = std::max(begin, part.first), to = std::min(end, part.first + part.layout.rows);
            if (from < to) append_rows(parts.file(k), part.layout, from - part.first, to - part.first, set);
        }
    }
    if (begin > 0) {
        set.ids.resize(end - begin);
        for (std::size_t i = 0; i < set.ids.size(); ++i) set.ids[i] = begin + i;
    }
    return set;
}

void SnapshotRows::set_box(const PeriodicBox& box)
{
    for (auto& part : parts_->list) part.layout.header.box = box;
    parts_->sample.box = box;
}

bool is_snapshot(const std::filesystem::path& file)
{
    silence_hdf5();
    const OpenFile named(file);
    return named.file().exists("/PartType0");
}

} // namespace sphkern
