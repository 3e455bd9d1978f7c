// Particle sets from files: SWIFT, GADGET and PySPH HDF5, GADGET-2's binary snapshots, Phantom's
// dumps, CSV with a header line, and legacy VTK (ASCII or big-endian BINARY, POLYDATA or UNSTRUCTURED_GRID). Every
// error names the file, the dataset, column or array, and the particle id where there is one.
#pragma once

#include "particles/particle_set.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace sphkern {

enum class ParticleFileFormat { hdf5, csv, vtk, gadget_binary, phantom_dump };

struct ParticleFileOptions {
    // PySPH: the particle array (default: the only one, or "fluid"), or a comma-separated list:
    // measured on the first, the others' particles neighbours only (ParticleSet::neighbours_only).
    std::string array;
    std::optional<int> dimension; // 2: read a 3-column file whose one coordinate is constant as 2D
    // SPlisHSPlasH VTK: the scene's particle radius r, which its files do not hold (h = r, support 4 r).
    std::optional<double> particle_radius;
    std::size_t max_particles = 0;
};

// By extension (.h5, .hdf5, .csv, .vtk), else by the file's first bytes; nullopt if neither says.
// A GADGET snapshot in parts may be named by its base, BASE for BASE.0, BASE.1, ...
std::optional<ParticleFileFormat> particle_file_format(const std::filesystem::path& file);

// The file a name stands for: itself, or the first part BASE.0 of a GADGET binary snapshot named
// by its base (what a run's provenance hashes).
std::filesystem::path particle_file_named(const std::filesystem::path& file);

ParticleSet read_particle_file(const std::filesystem::path& file, const ParticleFileOptions& options);

ParticleSet read_csv_particles(const std::filesystem::path& file, const ParticleFileOptions& options);
ParticleSet read_vtk_particles(const std::filesystem::path& file, const ParticleFileOptions& options);
ParticleSet read_hdf5_particles(const std::filesystem::path& file, const ParticleFileOptions& options);
ParticleSet read_gadget_binary_particles(const std::filesystem::path& file, const ParticleFileOptions& options);
ParticleSet read_phantom_dump_particles(const std::filesystem::path& file, const ParticleFileOptions& options);

// For readers: keeps x, y, z as read, or turns a 3D set into 2D where asked (`dimension` 2) by
// dropping its one constant coordinate. Throws Error(input) if no coordinate is constant.
void apply_dimension(ParticleSet& set, const ParticleFileOptions& options);

} // namespace sphkern
