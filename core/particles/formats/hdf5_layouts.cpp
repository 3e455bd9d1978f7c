// SWIFT's, GADGET's and PySPH's HDF5 layouts of a particle set (particle_writers.hpp),
// each file built whole in memory and then written to its path atomically.
#include "particles/formats/particle_writers.hpp"

#include "support/error.hpp"
#include "support/io/atomic_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <functional>
#include <ostream>
#include <stdexcept>

namespace sphkern {

namespace {

// An HDF5 identifier closed on every path out; Error(output) naming `what` if it is invalid.
class Id {
public:
    Id(hid_t id, herr_t (*close)(hid_t), const char* what) : id_(id), close_(close)
    {
        if (id_ < 0) throw Error(ExitCode::output, std::string("HDF5 cannot create ") + what);
    }
    ~Id() { close_(id_); }
    Id(const Id&) = delete;
    Id& operator=(const Id&) = delete;
    hid_t get() const { return id_; }

private:
    hid_t id_;
    herr_t (*close_)(hid_t);
};

// Error(output) naming `what` for a negative status.
void check(herr_t status, const char* what)
{
    if (status < 0) throw Error(ExitCode::output, std::string("HDF5 cannot write ") + what);
}

// A group at `path`, with the groups above it.
Id new_group(hid_t file, const char* path)
{
    Id list(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "a link list");
    check(H5Pset_create_intermediate_group(list.get(), 1), path);
    return Id(H5Gcreate2(file, path, list.get(), H5P_DEFAULT, H5P_DEFAULT), H5Gclose, path);
}

// A one-dimensional attribute of `type` (values.size() elements).
template <class T>
void write_attribute(hid_t object, const char* name, hid_t type, const std::vector<T>& values)
{
    const hsize_t n = values.size();
    Id space(H5Screate_simple(1, &n, nullptr), H5Sclose, name);
    Id attr(H5Acreate2(object, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
    check(H5Awrite(attr.get(), type, values.data()), name);
}

// A scalar attribute of `type`.
template <class T>
void write_scalar_attribute(hid_t object, const char* name, hid_t type, const T& value)
{
    Id space(H5Screate(H5S_SCALAR), H5Sclose, name);
    Id attr(H5Acreate2(object, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
    check(H5Awrite(attr.get(), type, &value), name);
}

// A fixed-length string, as SWIFT writes its own.
void write_text_attribute(hid_t object, const char* name, const std::string& text)
{
    Id type(H5Tcopy(H5T_C_S1), H5Tclose, name);
    check(H5Tset_size(type.get(), std::max<std::size_t>(1, text.size())), name);
    Id space(H5Screate(H5S_SCALAR), H5Sclose, name);
    Id attr(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
    check(H5Awrite(attr.get(), type.get(), text.data()), name);
}

// values (a contiguous container) as `columns` columns (1: a one-dimensional dataset).
template <class Values>
void write_dataset(hid_t group, const char* name, hid_t type, const Values& values, hsize_t columns = 1)
{
    const hsize_t shape[2] = {values.size() / columns, columns};
    Id space(H5Screate_simple(columns == 1 ? 1 : 2, shape, nullptr), H5Sclose, name);
    Id set(H5Dcreate2(group, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, name);
    check(H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), name);
}

// The file `fill` writes, built in memory (HDF5's core driver without a backing store), then
// written to `path` atomically. HDF5's own error stack is not printed.
void write_file(const std::filesystem::path& path, const std::function<void(hid_t file)>& fill)
{
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    std::vector<char> image;
    {
        Id access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "a file access list");
        check(H5Pset_fapl_core(access.get(), 1 << 20, 0), "an in-memory file");
        Id file(H5Fcreate("sphkern-particles.h5", H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose,
                "an in-memory file");
        fill(file.get());
        check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "the file");
        const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
        if (size <= 0) throw Error(ExitCode::output, "HDF5 cannot write the file image");
        image.resize(static_cast<std::size_t>(size));
        if (H5Fget_file_image(file.get(), image.data(), image.size()) != size)
            throw Error(ExitCode::output, "HDF5 cannot write the file image");
    }
    write_file_atomically(path, [&](std::ostream& out) {
        out.write(image.data(), static_cast<std::streamsize>(image.size()));
    });
}

std::vector<double> coordinates_of(const ParticleSet& set)
{
    std::vector<double> xyz(3 * set.size());
    for (std::size_t i = 0; i < set.size(); ++i)
        xyz[3 * i] = set.x[i], xyz[3 * i + 1] = set.y[i], xyz[3 * i + 2] = set.z[i];
    return xyz;
}

template <class T>
std::vector<T> ids_from(std::size_t n, T first)
{
    std::vector<T> ids(n);
    for (std::size_t i = 0; i < n; ++i) ids[i] = first + static_cast<T>(i);
    return ids;
}

void write_swift(hid_t file, const ParticleSet& set, const ParticleOutput& output)
{
    Id header = new_group(file, "/Header");
    const Eigen::Matrix3d& e = set.box->edges;
    write_attribute(header.get(), "BoxSize", H5T_NATIVE_DOUBLE,
                    std::vector<double>{e(0, 0), e(1, 1), set.dimension == 3 ? e(2, 2) : 1.0});
    write_attribute(header.get(), "Dimension", H5T_NATIVE_INT, std::vector<int>{set.dimension});
    std::vector<unsigned long long> counts(6, 0);
    counts[0] = set.size();
    write_attribute(header.get(), "NumPart_Total", H5T_NATIVE_ULLONG, counts);
    write_attribute(header.get(), "NumPart_ThisFile", H5T_NATIVE_ULLONG, counts);
    write_attribute(header.get(), "NumPart_Total_HighWord", H5T_NATIVE_UINT, std::vector<unsigned>(6, 0u));
    write_attribute(header.get(), "Flag_Entropy_ICs", H5T_NATIVE_UINT, std::vector<unsigned>(6, 0u)); // u, not entropy
    write_attribute(header.get(), "Time", H5T_NATIVE_DOUBLE, std::vector<double>{0.0});
    write_attribute(header.get(), "MassTable", H5T_NATIVE_DOUBLE, std::vector<double>(6, 0.0));
    write_attribute(header.get(), "NumFilesPerSnapshot", H5T_NATIVE_INT, std::vector<int>{1});
    Id group = new_group(file, "/PartType0");
    const std::size_t n = set.size();
    write_dataset(group.get(), "Coordinates", H5T_NATIVE_DOUBLE, coordinates_of(set), 3);
    write_dataset(group.get(), "Masses", H5T_NATIVE_DOUBLE, std::vector<double>(n, output.mass));
    // SWIFT's initial conditions name it in the singular (its snapshots in the plural).
    write_dataset(group.get(), "SmoothingLength", H5T_NATIVE_DOUBLE, output.h);
    {
        Id h(H5Dopen2(group.get(), "SmoothingLength", H5P_DEFAULT), H5Dclose, "SmoothingLength");
        write_attribute(h.get(), "support_per_h", H5T_NATIVE_DOUBLE, std::vector<double>{output.support_per_h});
    }
    write_dataset(group.get(), "Velocities", H5T_NATIVE_DOUBLE, std::vector<double>(3 * n, 0.0), 3);
    write_dataset(group.get(), "InternalEnergy", H5T_NATIVE_DOUBLE, std::vector<double>(n, output.internal_energy));
    write_dataset(group.get(), "ParticleIDs", H5T_NATIVE_ULLONG, ids_from<unsigned long long>(n, 1));
    Id scheme = new_group(file, "/HydroScheme");
    write_attribute(scheme.get(), "Kernel gamma", H5T_NATIVE_DOUBLE, std::vector<double>{output.support_per_h});
    if (!output.kernel_label.empty()) write_text_attribute(scheme.get(), "Kernel function", output.kernel_label);
}

// GADGET's box is a cube of side BoxSize (a square in 2D, whose z is 0).
double gadget_box_side(const ParticleSet& set)
{
    const Eigen::Matrix3d& e = set.box->edges;
    const double side = e(0, 0);
    if (e(1, 1) != side || (set.dimension == 3 && e(2, 2) != side))
        fail_input(fmt::format("{}: GADGET's periodic box is a cube of side BoxSize; this box is {:.10g} x {:.10g}{}; "
                               "expected equal sides (tile the set to make them equal)",
                               set.name, e(0, 0), e(1, 1),
                               set.dimension == 3 ? fmt::format(" x {:.10g}", e(2, 2)) : ""));
    return side;
}

void write_gadget(hid_t file, const ParticleSet& set, const ParticleOutput& output)
{
    const double side = gadget_box_side(set);
    const std::size_t n = set.size();
    Id header = new_group(file, "/Header");
    std::vector<int> this_file(6, 0);
    std::vector<unsigned> low(6, 0u), high(6, 0u);
    this_file[0] = static_cast<int>(n), low[0] = static_cast<unsigned>(n & 0xffffffffu),
    high[0] = static_cast<unsigned>(n >> 32);
    write_attribute(header.get(), "NumPart_ThisFile", H5T_NATIVE_INT, this_file);
    write_attribute(header.get(), "NumPart_Total", H5T_NATIVE_UINT, low);
    write_attribute(header.get(), "NumPart_Total_HighWord", H5T_NATIVE_UINT, high);
    write_attribute(header.get(), "MassTable", H5T_NATIVE_DOUBLE,
                    std::vector<double>(6, 0.0)); // the masses per particle
    for (const char* name : {"Time", "Redshift", "Omega0", "OmegaLambda"})
        write_scalar_attribute(header.get(), name, H5T_NATIVE_DOUBLE, 0.0);
    write_scalar_attribute(header.get(), "HubbleParam", H5T_NATIVE_DOUBLE, 1.0);
    write_scalar_attribute(header.get(), "BoxSize", H5T_NATIVE_DOUBLE, side);
    write_scalar_attribute(header.get(), "NumFilesPerSnapshot", H5T_NATIVE_INT, 1);
    // GADGET reads the attributes it knows by name; this one tells a 2D set (TWODIMS, z = 0) from a
    // 3D one when the file is read back, as SWIFT's Dimension does.
    write_scalar_attribute(header.get(), "Dimension", H5T_NATIVE_INT, set.dimension);
    // read_ic reads Flag_Entropy_ICs into one int: a scalar (0: InternalEnergy is u).
    for (const char* name :
         {"Flag_Entropy_ICs", "Flag_Sfr", "Flag_Cooling", "Flag_StellarAge", "Flag_Metals", "Flag_Feedback"})
        write_scalar_attribute(header.get(), name, H5T_NATIVE_INT, 0);
    write_scalar_attribute(header.get(), "Flag_DoublePrecision", H5T_NATIVE_INT, 1);
    Id group = new_group(file, "/PartType0");
    write_dataset(group.get(), "Coordinates", H5T_NATIVE_DOUBLE, coordinates_of(set), 3);
    write_dataset(group.get(), "Velocities", H5T_NATIVE_DOUBLE, std::vector<double>(3 * n, 0.0), 3);
    // GADGET-2's ids are 32-bit unless built with LONGIDS.
    if (n < 0xffffffffu) write_dataset(group.get(), "ParticleIDs", H5T_NATIVE_UINT, ids_from<unsigned>(n, 1u));
    else write_dataset(group.get(), "ParticleIDs", H5T_NATIVE_ULLONG, ids_from<unsigned long long>(n, 1));
    write_dataset(group.get(), "Masses", H5T_NATIVE_DOUBLE, std::vector<double>(n, output.mass));
    write_dataset(group.get(), "InternalEnergy", H5T_NATIVE_DOUBLE, std::vector<double>(n, output.internal_energy));
    write_dataset(group.get(), "SmoothingLength", H5T_NATIVE_DOUBLE, output.h);
}

// One of PySPH's arrays with the attributes its HDFOutput gives every property.
template <class Values>
void write_pysph_array(hid_t arrays, const char* name, hid_t type, const char* type_name, const Values& values)
{
    write_dataset(arrays, name, type, values);
    Id data(H5Dopen2(arrays, name, H5P_DEFAULT), H5Dclose, name);
    write_text_attribute(data.get(), "name", name);
    write_text_attribute(data.get(), "type", type_name);
    write_scalar_attribute(data.get(), "default", type, typename Values::value_type{});
    write_scalar_attribute(data.get(), "stored", H5T_NATIVE_HBOOL, static_cast<hbool_t>(true));
    write_scalar_attribute(data.get(), "stride", H5T_NATIVE_INT, 1);
}

void write_pysph(hid_t file, const ParticleSet& set, const ParticleOutput& output)
{
    const std::size_t n = set.size();
    Id solver = new_group(file, "/solver_data");
    write_scalar_attribute(solver.get(), "t", H5T_NATIVE_DOUBLE, 0.0);
    write_scalar_attribute(solver.get(), "dt", H5T_NATIVE_DOUBLE, 0.0);
    write_scalar_attribute(solver.get(), "count", H5T_NATIVE_INT, 0);
    Id constants = new_group(file, "/particles/fluid/constants");
    Id arrays = new_group(file, "/particles/fluid/arrays");
    const std::vector<double> zeros(n, 0.0);
    write_pysph_array(arrays.get(), "x", H5T_NATIVE_DOUBLE, "double", set.x);
    write_pysph_array(arrays.get(), "y", H5T_NATIVE_DOUBLE, "double", set.y);
    write_pysph_array(arrays.get(), "z", H5T_NATIVE_DOUBLE, "double", set.z);
    for (const char* name : {"u", "v", "w", "p"})
        write_pysph_array(arrays.get(), name, H5T_NATIVE_DOUBLE, "double", zeros);
    write_pysph_array(arrays.get(), "m", H5T_NATIVE_DOUBLE, "double", std::vector<double>(n, output.mass));
    write_pysph_array(arrays.get(), "h", H5T_NATIVE_DOUBLE, "double", output.h);
    write_pysph_array(arrays.get(), "rho", H5T_NATIVE_DOUBLE, "double", std::vector<double>(n, output.density));
    write_pysph_array(arrays.get(), "tag", H5T_NATIVE_INT, "int", std::vector<int>(n, 0)); // local particles
    write_pysph_array(arrays.get(), "pid", H5T_NATIVE_INT, "int", std::vector<int>(n, 0));
    write_pysph_array(arrays.get(), "gid", H5T_NATIVE_UINT, "unsigned int", ids_from<unsigned>(n, 0u));
}

} // namespace

void require_layout_box(const ParticleSet& set, ParticleLayout layout, const std::string& what)
{
    require_rectangular_box(set, what);
    if (layout == ParticleLayout::gadget) gadget_box_side(set);
}

void write_hdf5_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output)
{
    if (output.layout == ParticleLayout::phantom) throw std::logic_error("a Phantom dump is not an HDF5 file");
    const char* layouts[] = {"SWIFT's", "GADGET's", "PySPH's"};
    require_layout_box(set, output.layout,
                       fmt::format("an HDF5 file in {} layout", layouts[static_cast<int>(output.layout)]));
    if (output.h.size() != set.size()) throw std::logic_error("a particle file needs one h per particle");
    write_file(file, [&](hid_t f) {
        if (output.layout == ParticleLayout::swift) write_swift(f, set, output);
        else if (output.layout == ParticleLayout::gadget) write_gadget(f, set, output);
        else write_pysph(f, set, output);
    });
}

} // namespace sphkern
