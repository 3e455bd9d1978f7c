// What `sphkern particles` prints and writes: the statistics as a table or JSON, and the
// per-particle values as CSV, legacy VTK or VTK XML (.vtu) (point data, for ParaView).
#pragma once

#include "particles/particle_analysis.hpp"
#include "particles/slabs/particles_in_slabs.hpp"
#include "requests/particles_request.hpp"
#include "support/io/chunked_writer.hpp"

#include <nlohmann/json_fwd.hpp>

#include <ostream>

namespace sphkern {

nlohmann::json summary_json(const Summary& summary);
nlohmann::json phases_json(const PhaseTimes& phases);  // {"phase": seconds, ...}
nlohmann::json point_json(const ParticlePoint& point); // eta, N_H, neighbours and the statistics of one h
// With the code the h came from, where `asked` names one ("code" in the JSON, a line in the text).
nlohmann::json particle_answer_json(const Kernel& kernel, const ParticleSet& set, const ParticleAnswer& answer,
                                    const ParticleArguments& asked);
void print_particle_answer(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const ParticleAnswer& answer,
                           const ParticleArguments& asked);

// One row per particle in id order: id, x, y, [z,] h, volume, neighbours, e0, eps_rho,
// eps_gradp, e1_x, e1_y[, e1_z], m1_x, m1_y[, m1_z]. Needs a single h (answer.measures).
void write_particle_csv(std::ostream& out, const ParticleSet& set, const ParticleAnswer& answer);
// The same rows streamed run by run from a set measured in slabs (`dimension` its D): the header
// with the first call, the bytes the whole set in memory gives.
class ParticleCsvRows {
public:
    ParticleCsvRows(std::ostream& out, int dimension, int threads);
    void write(const MeasuredRows& rows);

private:
    ChunkedWriter out_;
    bool three_;
    int threads_;
};
void write_particle_vtk(std::ostream& out, const ParticleSet& set, const ParticleAnswer& answer);
// The same values as ParaView's XML UnstructuredGrid: the points (z = 0 in 2D) and, as point
// data named as the CSV's columns, id, h, volume, neighbours, e0, eps_rho, eps_gradp and the
// vectors e1 and m1 (3 components, z = 0 in 2D), each a double written as it is.
void write_particle_vtu(std::ostream& out, const ParticleSet& set, const ParticleAnswer& answer);

} // namespace sphkern
