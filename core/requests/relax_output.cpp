#include "requests/relax_output.hpp"

#include "particles/formats/particle_writers.hpp"
#include "particles/tiled_set.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace sphkern {

void check_relax_output_settings(const RelaxOutput& output, FrontEnd front_end)
{
    const ValueSource file = value_named(front_end, "output");
    for (const auto& [value, key] : {std::pair{output.rho0, "rho0"}, std::pair{output.u, "u"}}) {
        if (!value) continue;
        const ValueSource source = value_named(front_end, key);
        check_positive(*value, source);
        if (output.file.empty())
            throw Error(source.code,
                        fmt::format("{} sets what {} writes; expected {} too", source.name, file.name, file.name));
    }
    const ValueSource u = value_named(front_end, "u");
    if (output.u && output.file.ends_with(".csv"))
        u.fail(fmt::format("{} holds x, y[, z], h and m, no internal energy; expected an .h5 or .hdf5 {} (or a "
                           "Phantom dump)",
                           output.file, file.name));
    const ValueSource tile = value_named(front_end, "tile");
    if (!output.tile.empty() && output.file.empty())
        throw Error(tile.code,
                    fmt::format("{} copies the set {} writes; expected {} too", tile.name, file.name, file.name));
}

WrittenSet write_relaxed_set(const Kernel& kernel, const RelaxResult& run, const RelaxOutput& output,
                             const RelaxSettings& settings, const std::optional<RelaxCode>& code,
                             const std::array<int, 3>& tiles)
{
    const ParticleSet tiled = output.tile.empty() ? ParticleSet{} : tiled_set(run.state.set, tiles, settings.threads);
    const ParticleSet& out = output.tile.empty() ? run.state.set : tiled;
    write_particle_file(output.file, out,
                        initial_conditions(kernel, out, run, {settings.gamma, output.rho0.value_or(1), output.u}, code,
                                           settings.threads),
                        settings.threads);
    const char* layouts[] = {"SWIFT HDF5", "GADGET HDF5", "PySPH HDF5", "Phantom full dump"};
    const std::string layout = output.file.ends_with(".csv") ? "CSV" : layouts[static_cast<int>(relax_layout(code))];
    return {std::filesystem::absolute(output.file).lexically_normal().string(), layout, out.size()};
}

std::string written_text(const WrittenSet& w)
{
    return fmt::format("wrote {}: {} particles, {} layout", w.file, w.particles, w.layout);
}

nlohmann::json written_json(const WrittenSet& w)
{
    return {{"file", w.file}, {"particles", w.particles}, {"layout", w.layout}};
}

RelaxResult relax_until_diverged(const Kernel& kernel, ParticleSet set, double h, const RelaxSettings& settings,
                                 const std::function<void(const RelaxState&, const RelaxStep&)>& observe,
                                 const std::string& history,
                                 const std::function<void(const std::vector<RelaxStep>&)>& write_history)
{
    try {
        return relax_particles(kernel, std::move(set), h, settings, observe);
    } catch (const RelaxDiverged& e) {
        if (history.empty()) throw;
        write_history(e.history);
        throw Error(e.code(),
                    fmt::format("{}; the history up to step {} is in {}", e.what(), e.history.back().step, history));
    }
}

} // namespace sphkern
