// Writing a particle set so that `sphkern particles` and the codes can read it back: HDF5 in
// SWIFT's, GADGET's or PySPH's layout, a Phantom full dump, or CSV with a header line. All need
// a rectangular periodic box (SWIFT's BoxSize and `--box` hold three sides).
#pragma once

#include "particles/particle_set.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// The layouts a set is written in, each as its code reads initial conditions: HDF5 for SWIFT,
// GADGET and PySPH, Phantom's own full dump (phantom_dump_writer.hpp).
enum class ParticleLayout { swift, gadget, pysph, phantom };

// What is written beside the positions: the stored h of every particle in the layout's
// convention, the support radius over it (SWIFT's "Kernel gamma"), one mass for all, the
// density m / V of the set, one internal energy and, for SWIFT, the kernel's name. HDF5 holds
// what the layout's code reads as initial conditions (velocities zero).
struct ParticleOutput {
    std::vector<double> h;
    double support_per_h = 0; // the support radius over h: SWIFT's "Kernel gamma", GADGET's 1
    double mass = 0;
    double density = 0;                            // of every particle at rest (PySPH's rho)
    std::string kernel_label;                      // SWIFT's "Kernel function", if the kernel is one of SWIFT's
    double internal_energy = 0;                    // u of every particle (SWIFT's and GADGET's InternalEnergy), at rest
    ParticleLayout layout = ParticleLayout::swift; // of a .h5 or .hdf5 file, or a Phantom dump
    // Phantom's dump only: its hfact, h = hfact (m / rho)^(1/D) for the rho the written h is of,
    // and the gas at rest that u is of (adiabatic index, sound speed).
    double hfact = 0;
    double eos_gamma = 0, sound_speed = 0;
};

// Throws Error(input) unless the set has a box whose edges lie along the axes.
void require_rectangular_box(const ParticleSet& set, const std::string& what);
// And for GADGET's layout, a cube (a square in 2D): checked before a run whose set it writes.
void require_layout_box(const ParticleSet& set, ParticleLayout layout, const std::string& what);

// The HDF5 layouts, each written whole into memory, then to `file` atomically:
// - swift: /Header (BoxSize, Dimension, NumPart_Total, NumPart_ThisFile, MassTable,
//   NumFilesPerSnapshot, Flag_Entropy_ICs), /HydroScheme "Kernel gamma" and "Kernel function",
//   /PartType0 Coordinates, Velocities, Masses, SmoothingLength (with the attribute
//   "support_per_h"), InternalEnergy, ParticleIDs; no /Units (SWIFT then takes its internal units);
// - gadget: the /Header GADGET-2's read_ic reads (NumPart_ThisFile, NumPart_Total,
//   NumPart_Total_HighWord, MassTable, Time, NumFilesPerSnapshot, a scalar Flag_Entropy_ICs)
//   and GADGET-4's (Redshift, BoxSize), /PartType0 Coordinates, Velocities, ParticleIDs,
//   Masses, InternalEnergy, SmoothingLength (the support radius). GADGET's box is a cube of
//   side BoxSize: another box is refused (Error(input));
// - pysph: /particles/fluid/arrays x, y, z, u, v, w, m, h, rho, p, tag, pid, gid with the
//   attributes PySPH's HDFOutput writes (name, type, default, stored, stride),
//   /particles/fluid/constants and /solver_data (t, dt, count): what pysph.solver.utils.load
//   reads. PySPH's periodic domain is its application's, not the file's.
void write_hdf5_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output);

// x,y[,z],h,m with 17 significant digits, after comment lines that state the box and R; the
// rows formatted on `threads` threads (0: every core), written in order (the text does not
// depend on them).
void write_csv_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output,
                         int threads = 1);

// Error(usage) for a name that does not end in .h5, .hdf5 or .csv ("x.txt: expected ..."); in
// Phantom's layout, for one that ends in .h5 or .hdf5 (a Phantom dump takes any other name).
void check_particle_output_name(const std::filesystem::path& file, ParticleLayout layout = ParticleLayout::swift);
// By extension: .csv (its rows formatted on `threads` threads), else a Phantom dump in
// Phantom's layout, else .h5/.hdf5 (output.layout).
void write_particle_file(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output,
                         int threads = 1);

} // namespace sphkern
