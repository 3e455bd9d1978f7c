#include "particles/formats/particle_files.hpp"

#include "particles/formats/gadget_records.hpp"
#include "particles/formats/phantom_records.hpp"

#include "support/error.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <fstream>

namespace sphkern {

std::optional<ParticleFileFormat> particle_file_format(const std::filesystem::path& file)
{
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".h5" || ext == ".hdf5" || ext == ".hdf") return ParticleFileFormat::hdf5;
    if (ext == ".csv") return ParticleFileFormat::csv;
    if (ext == ".vtk") return ParticleFileFormat::vtk;
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        const std::filesystem::path first_part = file.string() + ".0";
        if (std::filesystem::is_regular_file(first_part, ec) && is_gadget_binary(first_part))
            return ParticleFileFormat::gadget_binary;
        return std::nullopt;
    }
    if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
    char head[16] = {};
    std::ifstream in(file, std::ios::binary);
    in.read(head, sizeof head);
    if (std::memcmp(head, "\x89HDF\r\n\x1a\n", 8) == 0) return ParticleFileFormat::hdf5;
    if (std::memcmp(head, "# vtk DataFile", 14) == 0) return ParticleFileFormat::vtk;
    if (is_gadget_binary(file)) return ParticleFileFormat::gadget_binary;
    if (is_phantom_dump(file)) return ParticleFileFormat::phantom_dump;
    return std::nullopt;
}

std::filesystem::path particle_file_named(const std::filesystem::path& file)
{
    std::error_code ec;
    const std::filesystem::path first_part = file.string() + ".0";
    if (!std::filesystem::exists(file, ec) && particle_file_format(file) == ParticleFileFormat::gadget_binary)
        return first_part;
    return file;
}

ParticleSet read_particle_file(const std::filesystem::path& file, const ParticleFileOptions& options)
{
    const auto format = particle_file_format(file);
    // A name of a known format that is not there (a GADGET or HDF5 snapshot in parts is named by
    // its base, which is no file; their readers say so); any other name is no particle file.
    std::error_code ec;
    if ((format == ParticleFileFormat::csv || format == ParticleFileFormat::vtk) && !std::filesystem::exists(file, ec))
        fail_missing(file.string() + ": no such file");
    if (!format)
        fail_input(file.string() + ": not a particle file; expected .h5/.hdf5 (SWIFT, GADGET, PySPH), .csv, .vtk "
                                   "a GADGET binary snapshot or a Phantom dump");
    if (!options.array.empty() && *format != ParticleFileFormat::hdf5)
        throw Error(ExitCode::usage, fmt::format("{} {}: names PySPH's particle arrays; {} holds one set",
                                                 setting_named("array"), options.array, file.string()));
    if (options.particle_radius && *format != ParticleFileFormat::vtk)
        throw Error(ExitCode::usage, fmt::format("{}: {} is not a VTK file; the radius gives the h of "
                                                 "SPlisHSPlasH's VTK files only",
                                                 setting_named("particle_radius"), file.string()));
    ParticleSet set = *format == ParticleFileFormat::hdf5            ? read_hdf5_particles(file, options)
                      : *format == ParticleFileFormat::csv           ? read_csv_particles(file, options)
                      : *format == ParticleFileFormat::vtk           ? read_vtk_particles(file, options)
                      : *format == ParticleFileFormat::gadget_binary ? read_gadget_binary_particles(file, options)
                                                                     : read_phantom_dump_particles(file, options);
    apply_dimension(set, options);
    if (options.max_particles && set.size() > options.max_particles)
        fail_input(fmt::format("{}: {} particles, more than the memory limit of {} ({})", file.string(), set.size(),
                               options.max_particles, setting_named("memory_limit")));
    return set;
}

void apply_dimension(ParticleSet& set, const ParticleFileOptions& options)
{
    if (!options.dimension || *options.dimension == set.dimension) return;
    if (*options.dimension != 2 || set.dimension != 3)
        fail_input(fmt::format("{0}: {3} {1} for a set with {2} coordinates; expected {3} 2 for a 3-column set",
                               set.name, *options.dimension, set.dimension, setting_named("dim")));
    auto constant = [](const ParticleValues& v) {
        return std::all_of(v.begin(), v.end(), [&](double c) { return c == v[0]; });
    };
    if (constant(set.z)) {
    } else if (constant(set.y)) {
        set.y.swap(set.z); // a 2D set in the x-z plane (DualSPHysics)
    } else if (constant(set.x)) {
        set.x.swap(set.y), set.y.swap(set.z);
    } else {
        fail_input(set.name + ": " + setting_named("dim") + " 2, but no coordinate is the same for every particle");
    }
    std::fill(set.z.begin(), set.z.end(), 0.0);
    set.dimension = 2;
    set.gravity = Eigen::Vector3d(0, -1, 0);
    if (set.box) set.box->edges.col(2) = Eigen::Vector3d::UnitZ(); // a box given for 3D keeps its x and y only
}

} // namespace sphkern
