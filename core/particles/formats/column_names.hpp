// The per-particle quantities sphkern reads from files, and the names codes give them in CSV
// headers and VTK arrays (DualSPHysics "Pos.x [m]", "Rhop"; SPlisHSPlasH "density").
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace sphkern {

enum class ParticleField { x, y, z, h, mass, density };

// The field a column or array name stands for, ignoring case and a trailing unit in brackets.
std::optional<ParticleField> particle_field(std::string_view name);
const char* field_name(ParticleField field);

} // namespace sphkern
