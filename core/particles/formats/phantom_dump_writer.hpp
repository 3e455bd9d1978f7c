// A particle set as a Phantom full dump that Phantom starts a run from: the mirror of
// read_phantom_dump_particles, in the layout of Phantom's readwrite_dumps.f90 (write_fulldump,
// read by read_dump) with the header readwrite_dumps_common.f90 fills (fill_header) and reads
// back (unfill_header, unfill_rheader). share/docs/particle-formats.md describes what it holds.
#pragma once

#include "particles/formats/particle_writers.hpp"

#include <filesystem>

namespace sphkern {

// One MPI block of gas particles (itype 1, so no itype array) at rest: x, y, z, h (real*8, the
// written h bit for bit; Phantom's own h is real*4), vx = vy = vz = 0 and u
// (output.internal_energy) as default reals (8 bytes), iorig 1..N (int*8); the header's
// nparttot, npartoftype, massoftype(1) = output.mass, hfact = output.hfact, gamma and the
// polytropic constant of the relaxation's pressure at rest, rhozero = output.density, the box
// (xmin = 0 ... zmax, sphkern's box from the origin) and code units of 1. Needs a 3D set in a
// rectangular periodic box (Error(input)); written atomically (Error(output)).
void write_phantom_dump(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output);

} // namespace sphkern
