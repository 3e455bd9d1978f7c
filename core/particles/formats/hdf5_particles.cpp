// HDF5 particle files through libhdf5's C API, with its own error printing switched off:
// SWIFT and GADGET snapshots and initial conditions (/Header, /PartType0) and PySPH output
// (/particles/<array>/arrays/<property>).
#include "particles/formats/particle_arrays.hpp"
#include "particles/formats/particle_files.hpp"
#include "particles/formats/swift_kernels.hpp"

#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/text/printable_text.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <regex>

namespace sphkern {

namespace {

// An HDF5 handle closed by its own close function.
class Handle {
public:
    Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
    ~Handle()
    {
        if (id_ >= 0) close_(id_);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }

private:
    hid_t id_;
    herr_t (*close_)(hid_t);
};

void silence_hdf5()
{
    static std::once_flag once;
    std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

// The files an HDF5 file reaches through external links and virtual datasets. Each is followed
// only to a regular file that exists (an open of a FIFO or a device would block, a missing part
// would read as fill values), and each is an input that no output may replace.
struct LinkedFiles {
    std::filesystem::path folder; // of the file read: relative names start there
    std::vector<std::string> files;
    std::string refusal; // why a link was not followed

    // `name` as libhdf5 looks for it: as given, under the prefixes of `prefix_variable`, beside the file.
    bool admit(const std::string& name, const char* prefix_variable, const std::string& what)
    {
        const std::filesystem::path given(name);
        std::vector<std::filesystem::path> places{given};
        if (given.is_relative()) {
            if (const char* prefixes = std::getenv(prefix_variable)) {
                std::string list = prefixes;
                for (std::size_t start = 0, end; start <= list.size(); start = end + 1) {
                    end = std::min(list.find(':', start), list.size());
                    if (end > start) places.push_back(std::filesystem::path(list.substr(start, end - start)) / given);
                }
            }
            places.push_back(folder / given);
        }
        bool found = false;
        for (const auto& place : places) {
            struct stat status {};
            if (::stat(place.c_str(), &status) != 0) continue;
            if (!S_ISREG(status.st_mode)) {
                refusal = fmt::format("{} leads to {}, which is not a regular file", what, place.string());
                return false;
            }
            files.push_back(place.lexically_normal().string());
            found = true;
        }
        if (!found) refusal = fmt::format("{} leads to {}, which does not exist", what, name);
        return found;
    }
};

extern "C" herr_t follow_external_link(const char*, const char* group, const char* child_file, const char* child_object,
                                       unsigned*, hid_t, void* data)
{
    auto& linked = *static_cast<LinkedFiles*>(data);
    return linked.admit(child_file, "HDF5_EXT_PREFIX",
                        fmt::format("the external link in {} to {}:{}", group, child_file, child_object))
               ? 0
               : -1;
}

struct File {
    std::string name;
    hid_t id;
    LinkedFiles* linked;
    // Link, dataset and group access, each following external links through follow_external_link.
    hid_t links, dataset_access, group_access;

    // Every lookup goes through here: a link that was refused is the error, not its symptom.
    void check_links() const
    {
        if (!linked->refusal.empty()) fail_input(fmt::format("{}: {}", name, linked->refusal));
    }
    bool exists(const std::string& path) const
    {
        const bool found = H5Lexists(id, path.c_str(), links) > 0;
        check_links();
        return found;
    }
    // A virtual dataset's source files, followed like external links; values stored outside the file refused.
    void check_sources(hid_t set, const std::string& path) const
    {
        Handle create(H5Dget_create_plist(set), H5Pclose);
        if (H5Pget_external_count(create.get()) > 0)
            fail_input(fmt::format("{}: dataset {} keeps its values in external raw files; expected them in the "
                                   "HDF5 file or a virtual dataset",
                                   name, path));
        if (H5Pget_layout(create.get()) != H5D_VIRTUAL) return;
        std::size_t count = 0;
        H5Pget_virtual_count(create.get(), &count);
        for (std::size_t i = 0; i < count; ++i) {
            const ssize_t length = H5Pget_virtual_filename(create.get(), i, nullptr, 0);
            std::string source(static_cast<std::size_t>(std::max<ssize_t>(length, 0)) + 1, '\0');
            H5Pget_virtual_filename(create.get(), i, source.data(), source.size());
            source.resize(static_cast<std::size_t>(std::max<ssize_t>(length, 0)));
            if (source == ".") continue; // the file itself
            linked->admit(source, "HDF5_VDS_PREFIX", fmt::format("the virtual dataset {} maps {}", path, source));
            check_links();
        }
    }

    // The rows a dataset declares, none read.
    std::size_t rows(const std::string& path) const
    {
        Handle set(H5Dopen2(id, path.c_str(), dataset_access), H5Dclose);
        check_links();
        if (!set.valid()) fail_input(fmt::format("{}: dataset {} cannot be opened", name, path));
        Handle space(H5Dget_space(set.get()), H5Sclose);
        hsize_t dims[2] = {0, 0};
        if (H5Sget_simple_extent_ndims(space.get()) < 1 || H5Sget_simple_extent_ndims(space.get()) > 2)
            fail_input(fmt::format("{}: dataset {} is not a table of rows", name, path));
        H5Sget_simple_extent_dims(space.get(), dims, nullptr);
        return static_cast<std::size_t>(dims[0]);
    }
    // A dataset of doubles (any stored number type is converted) with its shape.
    ParticleValues dataset(const std::string& path, std::vector<hsize_t>& shape) const
    {
        Handle set(H5Dopen2(id, path.c_str(), dataset_access), H5Dclose);
        check_links();
        if (!set.valid()) fail_input(fmt::format("{}: dataset {} cannot be opened", name, path));
        check_sources(set.get(), path);
        Handle space(H5Dget_space(set.get()), H5Sclose);
        const int rank = H5Sget_simple_extent_ndims(space.get());
        if (rank < 1 || rank > 2) fail_input(fmt::format("{}: dataset {} has rank {}; expected 1 or 2", name, path, rank));
        shape.assign(static_cast<std::size_t>(rank), 0);
        H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
        Handle type(H5Dget_type(set.get()), H5Tclose);
        const H5T_class_t kind = H5Tget_class(type.get());
        if (kind != H5T_FLOAT && kind != H5T_INTEGER)
            fail_input(fmt::format("{}: dataset {} does not hold numbers", name, path));
        // A declared size is checked against the budget before anything is allocated for it.
        double total = 1;
        for (auto s : shape) total *= static_cast<double>(s);
        if (static_cast<double>(shape[0]) > static_cast<double>(max_particles()) ||
            total * sizeof(double) > static_cast<double>(particle_file_byte_limit()))
            fail_input(fmt::format("{}: dataset {} declares {} rows ({:.4g} bytes to read, {:.4g} bytes for the "
                                   "particles); over the memory budget of {:.4g} bytes ({})",
                                   name, path, shape[0], total * sizeof(double),
                                   static_cast<double>(shape[0]) * bytes_per_particle,
                                   static_cast<double>(memory_limit_bytes()), setting_named("memory_limit")));
        ParticleValues values(static_cast<std::size_t>(total));
        if (!values.empty() && H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
            fail_input(fmt::format("{}: dataset {} cannot be read (a truncated file?)", name, path));
        return values;
    }
    ParticleValues column(const std::string& path, std::size_t count) const
    {
        std::vector<hsize_t> shape;
        auto values = dataset(path, shape);
        if (shape.size() != 1 || shape[0] != count)
            fail_input(fmt::format("{}: dataset {} has shape {}; expected ({})", name, path, shape_text(shape), count));
        return values;
    }
    // A numeric attribute of `object` with up to `max` values.
    std::vector<double> attribute(const std::string& object, const std::string& attr) const
    {
        if (!exists(object) || H5Aexists_by_name(id, object.c_str(), attr.c_str(), links) <= 0) return {};
        Handle a(H5Aopen_by_name(id, object.c_str(), attr.c_str(), H5P_DEFAULT, links), H5Aclose);
        check_links();
        Handle space(H5Aget_space(a.get()), H5Sclose);
        const hssize_t n = H5Sget_simple_extent_npoints(space.get());
        Handle type(H5Aget_type(a.get()), H5Tclose);
        const H5T_class_t kind = H5Tget_class(type.get());
        if (n <= 0 || n > 64 || (kind != H5T_FLOAT && kind != H5T_INTEGER))
            fail_input(fmt::format("{}: attribute {} of {} is not a short list of numbers", name, attr, object));
        std::vector<double> values(static_cast<std::size_t>(n));
        if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, values.data()) < 0)
            fail_input(fmt::format("{}: attribute {} of {} cannot be read", name, attr, object));
        return values;
    }
    // A text attribute of `object` (fixed or variable length), "" when there is none.
    std::string text_attribute(const std::string& object, const std::string& attr) const
    {
        if (!exists(object) || H5Aexists_by_name(id, object.c_str(), attr.c_str(), links) <= 0) return {};
        Handle a(H5Aopen_by_name(id, object.c_str(), attr.c_str(), H5P_DEFAULT, links), H5Aclose);
        check_links();
        Handle type(H5Aget_type(a.get()), H5Tclose);
        Handle space(H5Aget_space(a.get()), H5Sclose);
        if (H5Tget_class(type.get()) != H5T_STRING || H5Sget_simple_extent_npoints(space.get()) != 1) return {};
        std::string text;
        if (H5Tis_variable_str(type.get()) > 0) {
            char* value = nullptr;
            Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
            H5Tset_size(memory.get(), H5T_VARIABLE);
            if (H5Aread(a.get(), memory.get(), &value) >= 0 && value) text = value;
            if (value) H5free_memory(value);
        } else {
            const std::size_t size = H5Tget_size(type.get());
            if (size == 0 || size > 4096) return {};
            std::string buffer(size, '\0');
            if (H5Aread(a.get(), type.get(), buffer.data()) >= 0) text = buffer.c_str();
        }
        return printable_text(text);
    }
    static std::string shape_text(const std::vector<hsize_t>& shape)
    {
        std::string text;
        for (auto s : shape) text += (text.empty() ? "" : ", ") + std::to_string(s);
        return "(" + text + ")";
    }
};

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

ParticleSet read_snapshot(const File& f)
{
    ParticleSet set;
    set.name = f.name;
    const auto dimension = f.attribute("/Header", "Dimension");
    if (!dimension.empty() && dimension[0] != 2 && dimension[0] != 3)
        fail_input(fmt::format("{}: /Header Dimension is {}; expected 2 or 3", f.name, dimension[0]));
    set.dimension = dimension.empty() ? 3 : static_cast<int>(dimension[0]);
    std::vector<hsize_t> shape;
    const auto coordinates = f.dataset("/PartType0/Coordinates", shape);
    if (shape.size() != 2 || (shape[1] != 3 && shape[1] != static_cast<hsize_t>(set.dimension)))
        fail_input(fmt::format("{}: /PartType0/Coordinates has shape {}; expected (N, 3)", f.name, File::shape_text(shape)));
    const std::size_t n = static_cast<std::size_t>(shape[0]), columns = static_cast<std::size_t>(shape[1]);
    const auto counts = f.attribute("/Header", "NumPart_Total"), this_file = f.attribute("/Header", "NumPart_ThisFile");
    const auto files = f.attribute("/Header", "NumFilesPerSnapshot");
    if (!this_file.empty() && static_cast<std::size_t>(this_file[0]) != n)
        fail_input(fmt::format("{}: /Header NumPart_ThisFile[0] is {} but /PartType0/Coordinates has {} rows", f.name, this_file[0], n));
    if (!counts.empty() && static_cast<std::size_t>(counts[0]) != n && (files.empty() || files[0] <= 1) &&
        f.attribute("/Header", "NumPart_Total_HighWord").empty())
        fail_input(fmt::format("{}: /Header NumPart_Total[0] is {} but /PartType0/Coordinates has {} rows", f.name, counts[0], n));
    for (std::size_t i = 0; i < n; ++i) {
        set.x.push_back(coordinates[i * columns]);
        set.y.push_back(coordinates[i * columns + 1]);
        set.z.push_back(set.dimension == 3 ? coordinates[i * columns + 2] : 0.0);
    }
    if (set.dimension == 2) set.gravity = Eigen::Vector3d(0, -1, 0);
    auto optional_column = [&](std::initializer_list<const char*> names) -> ParticleValues {
        for (const char* dataset : names)
            if (f.exists("/PartType0") && f.exists(std::string("/PartType0/") + dataset))
                return f.column(std::string("/PartType0/") + dataset, n);
        return {};
    };
    set.h = optional_column({"SmoothingLengths", "SmoothingLength"});
    set.mass = optional_column({"Masses", "Mass"});
    set.density = optional_column({"Densities", "Density"});
    const auto table = f.attribute("/Header", "MassTable");
    if (set.mass.empty() && !table.empty() && table[0] > 0) set.mass.assign(n, table[0]);
    const auto box = f.attribute("/Header", "BoxSize");
    if (!box.empty()) {
        PeriodicBox b;
        for (int a = 0; a < 3; ++a) b.edges(a, a) = box.size() >= 3 ? box[static_cast<std::size_t>(a)] : box[0];
        if (set.dimension == 2) b.edges(2, 2) = 1;
        set.box = b;
    }
    const auto gamma = f.attribute("/HydroScheme", "Kernel gamma");
    if (!gamma.empty()) set.support_per_h = gamma[0];
    // GADGET's SmoothingLength is the radius where its kernel reaches zero.
    if (written_by_gadget(f)) set.support_per_h = 1;
    set.file_kernel = f.text_attribute("/HydroScheme", "Kernel function");
    set.file_kernel_name = sphkern_kernel_of_swift(set.file_kernel);
    return set;
}

// The names of the particle arrays under /particles, in the file's name order.
std::vector<std::string> pysph_array_names(const File& f)
{
    std::vector<std::string> names;
    Handle group(H5Gopen2(f.id, "/particles", f.group_access), H5Gclose);
    f.check_links();
    H5G_info_t info{};
    H5Gget_info(group.get(), &info);
    for (hsize_t i = 0; i < info.nlinks && i < 1000; ++i) {
        // A name of any length: its size asked first.
        const ssize_t length = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, f.links);
        if (length <= 0) fail_input(fmt::format("{}: the name of particle array {} cannot be read", f.name, i));
        std::string name(static_cast<std::size_t>(length) + 1, '\0');
        H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), f.links);
        name.resize(static_cast<std::size_t>(length));
        names.push_back(std::move(name));
    }
    if (names.empty()) fail_input(fmt::format("{}: /particles holds no particle array; expected /particles/<array>/arrays/x, y[, z]", f.name));
    return names;
}

// The arrays asked for (default: the only one, or "fluid"), each one the file has.
std::vector<std::string> chosen_pysph_arrays(const File& f, const std::string& requested)
{
    const auto names = pysph_array_names(f);
    std::string listed;
    for (const auto& n : names) listed += (listed.empty() ? "" : ", ") + n;
    if (const std::string problem = particle_array_list_problem(requested); !problem.empty())
        fail_input(fmt::format("{}: the array list \"{}\": {}", f.name, requested, problem));
    auto chosen = particle_array_names(requested);
    if (chosen.empty()) {
        if (names.size() == 1) chosen = names;
        else if (std::find(names.begin(), names.end(), "fluid") != names.end()) chosen = {"fluid"};
        else fail_input(fmt::format("{}: several particle arrays ({}); choose one with {} NAME", f.name, listed, setting_named("array")));
    }
    for (const auto& array : chosen)
        if (std::find(names.begin(), names.end(), array) == names.end())
            fail_input(fmt::format("{}: no particle array \"{}\"; the file has {}", f.name, array, listed));
    return chosen;
}

// One array's x, y, z, h, m and rho (each of the last four empty where the file has none).
ParticleSet read_pysph_array(const File& f, const std::string& array)
{
    const std::string base = "/particles/" + array + "/arrays/";
    if (!f.exists(base + "x") || !f.exists(base + "y"))
        fail_input(fmt::format("{}: {}x and {}y are missing; expected PySPH arrays x, y[, z][, h][, m][, rho]", f.name,
                               base, base));
    std::vector<hsize_t> shape;
    ParticleSet set;
    set.name = f.name;
    set.x = f.dataset(base + "x", shape);
    const std::size_t n = set.x.size();
    set.y = f.column(base + "y", n);
    // PySPH's dump writes a property it was not asked to output as an empty dataset (its
    // attribute "stored" false): absent, as if it were not in the file.
    auto optional_column = [&](const char* p) {
        const std::string path = base + p;
        if (!f.exists(path) || (n > 0 && f.rows(path) == 0)) return ParticleValues{};
        return f.column(path, n);
    };
    set.z = optional_column("z");
    if (set.z.empty()) set.z.assign(n, 0.0);
    set.h = optional_column("h");
    set.mass = optional_column("m");
    set.density = optional_column("rho");
    return set;
}

// The neighbours-only arrays' particles after the measured ones. A property the first array
// has must be in every array (each particle needs it); one it lacks is left out of all.
void append_pysph_array(ParticleSet& set, ParticleSet&& more, const std::string& first, const std::string& array)
{
    const std::pair<ParticleValues*, ParticleValues*> columns[] = {{&set.h, &more.h}, {&set.mass, &more.mass}, {&set.density, &more.density}};
    const char* names[] = {"h", "m", "rho"};
    for (std::size_t c = 0; c < 3; ++c)
        if (!columns[c].first->empty() && columns[c].second->empty())
            fail_input(fmt::format("{}: particle array \"{}\" has no {}, which \"{}\" has; expected it in every array read",
                                   set.name, array, names[c], first));
    for (const auto& [whole, piece] : columns)
        if (!whole->empty()) whole->insert(whole->end(), piece->begin(), piece->end());
    for (const auto& [whole, piece] : {std::pair{&set.x, &more.x}, std::pair{&set.y, &more.y}, std::pair{&set.z, &more.z}})
        whole->insert(whole->end(), piece->begin(), piece->end());
    set.neighbours_only += more.size();
}

ParticleSet read_pysph(const File& f, const std::string& requested)
{
    const auto arrays = chosen_pysph_arrays(f, requested);
    ParticleSet set = read_pysph_array(f, arrays.front());
    for (std::size_t a = 1; a < arrays.size(); ++a) append_pysph_array(set, read_pysph_array(f, arrays[a]), arrays.front(), arrays[a]);
    // PySPH keeps z (zero) for 2D runs.
    const bool flat = std::all_of(set.z.begin(), set.z.end(), [](double z) { return z == 0; });
    set.dimension = flat ? 2 : 3;
    if (flat) set.gravity = Eigen::Vector3d(0, -1, 0);
    return set;
}

// An HDF5 file opened for reading, every link followed through follow_external_link.
class OpenFile {
public:
    explicit OpenFile(const std::filesystem::path& file)
        : linked_{std::filesystem::absolute(file).parent_path(), {}, {}}, handle_(open(file), H5Fclose),
          links_(H5Pcreate(H5P_LINK_ACCESS), H5Pclose), dataset_access_(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose),
          group_access_(H5Pcreate(H5P_GROUP_ACCESS), H5Pclose),
          file_{file.string(), handle_.get(), &linked_, links_.get(), dataset_access_.get(), group_access_.get()}
    {
        for (hid_t list : {links_.get(), dataset_access_.get(), group_access_.get()})
            H5Pset_elink_cb(list, follow_external_link, &linked_);
    }
    const File& file() const { return file_; }
    const std::vector<std::string>& linked_files() const { return linked_.files; }

private:
    static hid_t open(const std::filesystem::path& file)
    {
        const std::string name = file.string();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec)) fail_input(name + ": no such file");
        if (H5Fis_hdf5(file.c_str()) <= 0) fail_input(name + ": not an HDF5 file");
        const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        if (id < 0) fail_input(name + ": cannot be opened as HDF5 (a truncated file?)");
        return id;
    }
    LinkedFiles linked_;
    Handle handle_, links_, dataset_access_, group_access_;
    File file_;
};

// The gas particles a snapshot's header declares in all its files (NumPart_Total and its high word).
double declared_total(const File& f)
{
    const auto low = f.attribute("/Header", "NumPart_Total"), high = f.attribute("/Header", "NumPart_Total_HighWord");
    return (low.empty() ? 0.0 : low[0]) + (high.empty() ? 0.0 : high[0] * 4294967296.0);
}

// The name of part k of the snapshot whose part is `file` (BASE.K.hdf5), none if it has no such name.
std::optional<std::filesystem::path> part_name(const std::filesystem::path& file, std::size_t k)
{
    static const std::regex part(R"((.*)\.(\d+)\.(hdf5|h5))");
    std::smatch m;
    const std::string name = file.string();
    if (!std::regex_match(name, m, part)) return std::nullopt;
    return std::filesystem::path(fmt::format("{}.{}.{}", m[1].str(), k, m[3].str()));
}

// Every part's header must be the first's: the parts of one snapshot.
void check_same_header(const File& first, const File& part)
{
    for (const char* attr : {"NumFilesPerSnapshot", "NumPart_Total", "NumPart_Total_HighWord", "BoxSize", "MassTable", "Dimension"})
        if (part.attribute("/Header", attr) != first.attribute("/Header", attr))
            fail_input(fmt::format("{}: /Header {} differs from {}'s; expected the parts of one snapshot", part.name, attr,
                                   first.name));
}

void append_part(ParticleSet& set, ParticleSet&& part, const std::string& part_name)
{
    const std::pair<ParticleValues*, ParticleValues*> columns[] = {
        {&set.x, &part.x}, {&set.y, &part.y}, {&set.z, &part.z}, {&set.h, &part.h}, {&set.mass, &part.mass}, {&set.density, &part.density}};
    const bool first = set.x.empty();
    for (const auto& [whole, piece] : columns) {
        if (!first && whole->empty() != piece->empty())
            fail_input(fmt::format("{}: its smoothing lengths, masses or densities are {} where the first part's are {}; "
                                   "expected the parts of one snapshot",
                                   part_name, piece->empty() ? "missing" : "present", whole->empty() ? "missing" : "present"));
        whole->insert(whole->end(), piece->begin(), piece->end());
    }
    if (!first) return;
    set.dimension = part.dimension, set.gravity = part.gravity, set.box = part.box;
    set.support_per_h = part.support_per_h, set.file_kernel = part.file_kernel, set.file_kernel_name = part.file_kernel_name;
}

// A snapshot in one file, or in NumFilesPerSnapshot files BASE.0.hdf5 ... (SWIFT's distributed
// snapshots, GADGET's multi-part files) read in part order from any one of them. The budget
// is checked against the declared total before anything is read, and every part is an input.
ParticleSet read_snapshot_parts(const OpenFile& named, std::vector<std::string>& inputs)
{
    const File& f = named.file();
    const auto files = f.attribute("/Header", "NumFilesPerSnapshot");
    const double total = declared_total(f);
    if (files.empty() || files[0] <= 1 || static_cast<double>(f.rows("/PartType0/Coordinates")) >= total)
        return read_snapshot(f);
    const auto parts = static_cast<std::size_t>(files[0]);
    if (files[0] != std::floor(files[0]) || files[0] > 1e5)
        fail_input(fmt::format("{}: /Header NumFilesPerSnapshot is {}; expected a whole number of files", f.name, files[0]));
    if (!part_name(f.name, 0))
        fail_input(fmt::format("{}: one of {} files of a snapshot (/Header NumFilesPerSnapshot), but not named BASE.K.hdf5; "
                               "expected the parts' own names",
                               f.name, parts));
    if (total > static_cast<double>(max_particles()))
        fail_input(fmt::format("{}: the snapshot declares {:.0f} particles in {} files (/Header NumPart_Total; {:.4g} bytes "
                               "for the particles); over the memory budget of {:.4g} bytes ({})",
                               f.name, total, parts, total * bytes_per_particle, static_cast<double>(memory_limit_bytes()), setting_named("memory_limit")));
    ParticleSet set;
    for (std::size_t k = 0; k < parts; ++k) {
        const std::filesystem::path path = *part_name(f.name, k);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec))
            fail_input(fmt::format("{}: part {} of the snapshot's {} files, {}, does not exist; expected every part", f.name,
                                   k, parts, path.string()));
        const OpenFile part(path);
        check_same_header(f, part.file());
        append_part(set, read_snapshot(part.file()), path.string());
        inputs.push_back(path.lexically_normal().string());
        inputs.insert(inputs.end(), part.linked_files().begin(), part.linked_files().end());
    }
    if (static_cast<double>(set.x.size()) != total)
        fail_input(fmt::format("{}: the snapshot's {} files hold {} particles but /Header NumPart_Total declares {:.0f}; "
                               "expected the parts of one snapshot",
                               f.name, parts, set.x.size(), total));
    return set;
}

} // namespace

ParticleSet read_hdf5_particles(const std::filesystem::path& file, const ParticleFileOptions& options)
{
    silence_hdf5();
    const std::string name = file.string();
    std::error_code ec;
    // A snapshot named by its base (snap.hdf5 for snap.0.hdf5 ...): its parts are named instead.
    const std::filesystem::path first = file.parent_path() / (file.stem().string() + ".0" + file.extension().string());
    if (!std::filesystem::exists(file, ec) && std::filesystem::is_regular_file(first, ec))
        fail_input(fmt::format("{}: no such file; the snapshot is in parts: name one of them, such as {}", name, first.string()));
    const OpenFile named(file);
    const File& f = named.file();
    std::vector<std::string> inputs;
    ParticleSet set;
    if (f.exists("/PartType0")) {
        if (!f.exists("/PartType0/Coordinates"))
            fail_input(name + ": /PartType0/Coordinates is missing; expected a SWIFT or GADGET snapshot");
        set = read_snapshot_parts(named, inputs);
        set.name = name;
    } else if (f.exists("/particles")) {
        set = read_pysph(f, options.array);
    } else {
        fail_input(name + ": neither /PartType0 (SWIFT, GADGET) nor /particles (PySPH); expected a particle snapshot");
    }
    inputs.insert(inputs.end(), named.linked_files().begin(), named.linked_files().end());
    std::sort(inputs.begin(), inputs.end());
    inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
    set.linked_files = std::move(inputs);
    return set;
}

} // namespace sphkern
