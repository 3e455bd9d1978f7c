// Writing a particle set so that `sphkern particles` (and the codes whose layouts it reads)
// can read it back: HDF5 in SWIFT's layout, or CSV with a header line. Both need a
// rectangular periodic box (SWIFT's BoxSize and `--box` hold three sides).
#pragma once

#include "particles/particle_set.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// What is written beside the positions: the stored h of every particle, the support radius
// over it (SWIFT's "Kernel gamma"), one mass for all, one internal energy and, for SWIFT, the
// kernel's name. HDF5 holds what SWIFT reads as initial conditions (velocities zero).
struct ParticleOutput {
    std::vector<double> h;
    double support_per_h = 0;  // the support radius over h: SWIFT's "Kernel gamma"
    double mass = 0;
    std::string kernel_label;  // SWIFT's "Kernel function", if the kernel is one of SWIFT's
    double internal_energy = 0; // u of every particle (SWIFT's InternalEnergy), at rest
};

// Throws Error(input) unless the set has a box whose edges lie along the axes.
void require_rectangular_box(const ParticleSet& set, const std::string& what);

// /Header (BoxSize, Dimension, NumPart_Total, NumPart_ThisFile, MassTable, NumFilesPerSnapshot),
// /HydroScheme "Kernel gamma", /PartType0 Coordinates, Masses, SmoothingLengths (with the
// attribute "support_per_h" = R), ParticleIDs.
// Written whole into memory, then to `file` atomically.
void write_swift_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output);

// x,y[,z],h,m with 17 significant digits, after comment lines that state the box and R.
void write_csv_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output);

// Error(usage) for a name that does not end in .h5, .hdf5 or .csv ("x.txt: expected ...").
void check_particle_output_name(const std::filesystem::path& file);
// By extension: .h5/.hdf5 or .csv.
void write_particle_file(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output);

} // namespace sphkern
