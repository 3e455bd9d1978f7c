#include "particles/particle_volumes.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

namespace sphkern {

VolumeModel parse_volume_model(const std::string& name)
{
    if (name == "uniform") return VolumeModel::uniform;
    if (name == "file") return VolumeModel::file;
    if (name == "voronoi") return VolumeModel::voronoi;
    throw Error(ExitCode::usage, "\"" + name + "\" is unknown, expected uniform, file or voronoi",
                ErrorKind::unknown_name);
}

const char* volume_model_name(VolumeModel model)
{
    switch (model) {
    case VolumeModel::uniform: return "uniform";
    case VolumeModel::file: return "file";
    case VolumeModel::voronoi: return "voronoi";
    }
    return "";
}

VolumeModel default_volume_model(const ParticleSet& set)
{
    return !set.mass.empty() && !set.density.empty() ? VolumeModel::file : VolumeModel::uniform;
}

PerParticle particle_volumes(const ParticleSet& set, VolumeModel model, int threads)
{
    auto fill = [&](const auto& value) { return PerParticle::of(fill_particle_values(set.size(), threads, value)); };
    switch (model) {
    case VolumeModel::uniform:
        if (!set.box)
            fail_input(fmt::format(
                "{}: uniform volumes need a periodic box; expected a box, or each particle's volume (m / rho)",
                set.name));
        return PerParticle::same(set.size(), mean_volume(set));
    case VolumeModel::file:
        if (set.mass.empty() || set.density.empty())
            fail_input(
                fmt::format("{}: the file's volumes (m / rho) need masses and densities in the file; expected {}",
                            set.name, set.mass.empty() ? "masses" : "densities"));
        return fill([&](std::size_t i) { return set.mass[i] / set.density[i]; });
    case VolumeModel::voronoi: {
        if (!set.box) fail_input(fmt::format("{}: Voronoi volumes need a periodic box", set.name));
        const auto cells = voronoi_volumes(set);
        return fill([&](std::size_t i) { return cells[i]; });
    }
    }
    return {};
}

} // namespace sphkern
