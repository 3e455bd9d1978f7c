#include "particles/formats/column_names.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace sphkern {

std::optional<ParticleField> particle_field(std::string_view name)
{
    std::string key(name.substr(0, name.find('[')));
    key.erase(std::remove_if(key.begin(), key.end(), [](unsigned char c) { return std::isspace(c) || c == '"'; }),
              key.end());
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return std::tolower(c); });
    static const std::pair<const char*, ParticleField> names[] = {{"x", ParticleField::x},
                                                                  {"pos.x", ParticleField::x},
                                                                  {"pos_x", ParticleField::x},
                                                                  {"y", ParticleField::y},
                                                                  {"pos.y", ParticleField::y},
                                                                  {"pos_y", ParticleField::y},
                                                                  {"z", ParticleField::z},
                                                                  {"pos.z", ParticleField::z},
                                                                  {"pos_z", ParticleField::z},
                                                                  {"h", ParticleField::h},
                                                                  {"hsml", ParticleField::h},
                                                                  {"smoothinglength", ParticleField::h},
                                                                  {"smoothing_length", ParticleField::h},
                                                                  {"m", ParticleField::mass},
                                                                  {"mass", ParticleField::mass},
                                                                  {"masses", ParticleField::mass},
                                                                  {"rho", ParticleField::density},
                                                                  {"rhop", ParticleField::density},
                                                                  {"density", ParticleField::density},
                                                                  {"densities", ParticleField::density}};
    for (const auto& [alias, field] : names)
        if (key == alias) return field;
    return std::nullopt;
}

const char* field_name(ParticleField field)
{
    static const char* names[] = {"x", "y", "z", "h", "m", "rho"};
    return names[static_cast<int>(field)];
}

} // namespace sphkern
