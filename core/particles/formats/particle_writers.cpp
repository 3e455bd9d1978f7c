#include "particles/formats/particle_writers.hpp"

#include "support/error.hpp"
#include "support/io/atomic_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <memory>
#include <ostream>

namespace sphkern {

void require_rectangular_box(const ParticleSet& set, const std::string& what)
{
    if (!set.box) fail_input(fmt::format("{}: {} needs a periodic box", set.name, what));
    const Eigen::Matrix3d& e = set.box->edges;
    const double off = e(0, 1) * e(0, 1) + e(0, 2) * e(0, 2) + e(1, 0) * e(1, 0) + e(1, 2) * e(1, 2) +
                       (set.dimension == 3 ? e(2, 0) * e(2, 0) + e(2, 1) * e(2, 1) : 0.0);
    if (off > 1e-24 * e.squaredNorm())
        fail_input(fmt::format("{}: the periodic box is a parallelepiped, not a rectangular box; {} stores three sides "
                               "(a block of a lattice's rectangular cell, poisson or a file with a rectangular box)",
                               set.name, what));
}

namespace {


// An HDF5 identifier closed on every path out.
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

void check(herr_t status, const char* what)
{
    if (status < 0) throw Error(ExitCode::output, std::string("HDF5 cannot write ") + what);
}

template <class T>
void write_attribute(hid_t object, const char* name, hid_t type, const std::vector<T>& values)
{
    const hsize_t n = values.size();
    Id space(H5Screate_simple(1, &n, nullptr), H5Sclose, name);
    Id attr(H5Acreate2(object, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
    check(H5Awrite(attr.get(), type, values.data()), name);
}

// A fixed-length string, as SWIFT writes its own.
void write_text_attribute(hid_t object, const char* name, const std::string& text)
{
    Id type(H5Tcopy(H5T_C_S1), H5Tclose, name);
    check(H5Tset_size(type.get(), text.size()), name);
    Id space(H5Screate(H5S_SCALAR), H5Sclose, name);
    Id attr(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
    check(H5Awrite(attr.get(), type.get(), text.data()), name);
}

// Writes the dataset; `support_per_h` > 0 is stated on it as an attribute.
template <class T>
void write_dataset(hid_t group, const char* name, hid_t type, const std::vector<T>& values, hsize_t columns,
                   double support_per_h = 0)
{
    const hsize_t shape[2] = {values.size() / columns, columns};
    Id space(H5Screate_simple(columns == 1 ? 1 : 2, shape, nullptr), H5Sclose, name);
    Id set(H5Dcreate2(group, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, name);
    check(H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), name);
    if (support_per_h > 0) write_attribute(set.get(), "support_per_h", H5T_NATIVE_DOUBLE, std::vector<double>{support_per_h});
}

void write_header(hid_t file, const ParticleSet& set)
{
    Id header(H5Gcreate2(file, "/Header", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "/Header");
    const Eigen::Matrix3d& e = set.box->edges;
    write_attribute(header.get(), "BoxSize", H5T_NATIVE_DOUBLE, std::vector<double>{e(0, 0), e(1, 1), set.dimension == 3 ? e(2, 2) : 1.0});
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
}

void write_particles(hid_t file, const ParticleSet& set, const ParticleOutput& output)
{
    Id group(H5Gcreate2(file, "/PartType0", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "/PartType0");
    const std::size_t n = set.size();
    std::vector<double> coordinates(3 * n);
    for (std::size_t i = 0; i < n; ++i) coordinates[3 * i] = set.x[i], coordinates[3 * i + 1] = set.y[i], coordinates[3 * i + 2] = set.z[i];
    write_dataset(group.get(), "Coordinates", H5T_NATIVE_DOUBLE, coordinates, 3);
    write_dataset(group.get(), "Masses", H5T_NATIVE_DOUBLE, std::vector<double>(n, output.mass), 1);
    // SWIFT's initial conditions name it in the singular (its snapshots in the plural).
    write_dataset(group.get(), "SmoothingLength", H5T_NATIVE_DOUBLE, output.h, 1, output.support_per_h);
    write_dataset(group.get(), "Velocities", H5T_NATIVE_DOUBLE, std::vector<double>(3 * n, 0.0), 3);
    write_dataset(group.get(), "InternalEnergy", H5T_NATIVE_DOUBLE, std::vector<double>(n, output.internal_energy), 1);
    std::vector<unsigned long long> ids(n);
    for (std::size_t i = 0; i < n; ++i) ids[i] = i + 1;
    write_dataset(group.get(), "ParticleIDs", H5T_NATIVE_ULLONG, ids, 1);
    Id scheme(H5Gcreate2(file, "/HydroScheme", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "/HydroScheme");
    write_attribute(scheme.get(), "Kernel gamma", H5T_NATIVE_DOUBLE, std::vector<double>{output.support_per_h});
    if (!output.kernel_label.empty()) write_text_attribute(scheme.get(), "Kernel function", output.kernel_label);
}

// The whole file as bytes: built in memory (HDF5's core driver without a backing store).
std::vector<char> swift_image(const ParticleSet& set, const ParticleOutput& output)
{
    Id access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "a file access list");
    check(H5Pset_fapl_core(access.get(), 1 << 20, 0), "an in-memory file");
    Id file(H5Fcreate("sphkern-particles.h5", H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose, "an in-memory file");
    write_header(file.get(), set);
    write_particles(file.get(), set, output);
    check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "the file");
    const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
    if (size <= 0) throw Error(ExitCode::output, "HDF5 cannot write the file image");
    std::vector<char> image(static_cast<std::size_t>(size));
    if (H5Fget_file_image(file.get(), image.data(), image.size()) != size) throw Error(ExitCode::output, "HDF5 cannot write the file image");
    return image;
}

void check_output(const ParticleSet& set, const ParticleOutput& output, const std::string& what)
{
    require_rectangular_box(set, what);
    if (output.h.size() != set.size()) throw std::logic_error("a particle file needs one h per particle");
}

} // namespace

void write_swift_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output)
{
    check_output(set, output, "an HDF5 file in SWIFT's layout");
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const std::vector<char> image = swift_image(set, output);
    write_file_atomically(file, [&](std::ostream& out) { out.write(image.data(), static_cast<std::streamsize>(image.size())); });
}

void write_csv_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output)
{
    check_output(set, output, "a CSV particle file");
    const Eigen::Matrix3d& e = set.box->edges;
    write_file_atomically(file, [&](std::ostream& out) {
        out << fmt::format("# periodic box {:.17g} {:.17g}{}; support radius = {:.17g} h\n", e(0, 0), e(1, 1),
                           set.dimension == 3 ? fmt::format(" {:.17g}", e(2, 2)) : std::string(), output.support_per_h);
        out << (set.dimension == 3 ? "x,y,z,h,m\n" : "x,y,h,m\n");
        for (std::size_t i = 0; i < set.size(); ++i) {
            if (set.dimension == 3) out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", set.x[i], set.y[i], set.z[i], output.h[i], output.mass);
            else out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}\n", set.x[i], set.y[i], output.h[i], output.mass);
        }
    });
}

void check_particle_output_name(const std::filesystem::path& file)
{
    const std::string ext = file.extension().string();
    if (ext != ".h5" && ext != ".hdf5" && ext != ".csv")
        throw Error(ExitCode::usage, file.string() + ": expected a name ending in .h5, .hdf5 or .csv");
}

void write_particle_file(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output)
{
    check_particle_output_name(file);
    const std::string ext = file.extension().string();
    if (ext == ".csv") write_csv_particles(file, set, output);
    else write_swift_particles(file, set, output);
}

} // namespace sphkern
