#include "cli/source_options.hpp"

#include "cli/command.hpp"
#include "lattices/lattice.hpp"
#include "particles/formats/particle_arrays.hpp"
#include "particles/formats/particle_files.hpp"
#include "requests/source_request.hpp"
#include "support/error.hpp"
#include "support/io/sha256.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace sphkern::cli {

void add_source_options(Command c, SourceOptions& o)
{
    c.add_setting("source", o.source);
    c.add_setting("size", o.size);
    c.add_setting("cell", o.cell);
    c.add_setting("sigma", o.sigma);
    c.add_setting("seed", o.seed);
    c.add_setting("count", o.count);
    c.add_setting("dim", o.dim);
    c.add_setting("box", o.box);
    c.add_setting("particle_radius", o.particle_radius);
    c.add_setting("array", o.array);
}

ParticleSource source_of(const SourceOptions& o)
{
    return particle_source_of({o.source, o.size, o.box, o.array, o.cell, o.sigma, o.seed, o.count.value_or(0),
                               o.dim.value_or(0), o.particle_radius},
                              source_sources(FrontEnd::command_line));
}

std::unique_ptr<FileDigest> start_source_digest(const SourceOptions& o)
{
    if (source_kind(o.source) != SourceKind::file) return nullptr;
    return std::make_unique<FileDigest>(particle_file_named(o.source));
}

nlohmann::json source_inputs(const SourceOptions& o, const Kernel& kernel, FileDigest* digest)
{
    const auto kind = source_kind(o.source);
    std::optional<Lattice> lattice;
    if (kind == SourceKind::lattice) lattice = load_lattice(o.source);
    nlohmann::json inputs = command_inputs(&kernel, lattice ? &*lattice : nullptr);
    nlohmann::json source = {
        {"spec", o.source}, {"size", o.size},  {"sigma", o.sigma}, {"seed", o.seed}, {"count", o.count.value_or(0)},
        {"box", o.box},     {"array", o.array}};
    if (!o.cell.empty()) source["cell"] = o.cell;
    if (o.particle_radius) source["particle_radius"] = *o.particle_radius;
    if (kind == SourceKind::file)
        source["sha256"] = digest ? digest->get() : file_sha256_hex(particle_file_named(o.source));
    inputs["particles"] = source;
    return inputs;
}

} // namespace sphkern::cli
