#include "study/sections/section_table.hpp"

#include "study/sections/particles/particles_section.hpp"
#include "study/sections/stability/stability_section.hpp"
#include "study/sections/surface/surface_section.hpp"
#include "study/sections/sweeps/sweep_section.hpp"

namespace sphkern {

const std::vector<SectionKind>& section_table()
{
    static const std::vector<SectionKind> table = {
        {"surface", read_surface_section},
        {"sweeps", read_sweep_section},
        {"stability", read_stability_section},
        {"particles", read_particles_section},
    };
    return table;
}

} // namespace sphkern
