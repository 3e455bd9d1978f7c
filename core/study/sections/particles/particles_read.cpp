#include "study/sections/particles/particles_section.hpp"

#include "codes/code_table.hpp"
#include "requests/particles_request.hpp"
#include "requests/relax_request.hpp"
#include "requests/source_request.hpp"
#include "study/declared_keys.hpp"
#include "support/error.hpp"
#include "support/io/file_spec.hpp"

#include <fmt/format.h>

#include <climits>
#include <optional>

namespace sphkern {

namespace {

std::uint64_t seed_of(const JsonNode& node)
{
    const auto seed = node.find("seed");
    return seed ? static_cast<std::uint64_t>(seed->integer_in(0, 1LL << 53)) : 1;
}

// "eta" was sphkern's own h / l; it is refused naming its new key (SWIFT's eta is a code's setting).
void refuse_old_eta(const JsonNode& node)
{
    if (auto eta = node.find("eta"))
        eta->error(
            "\"eta\" is the old name of sphkern's own h over the mean spacing; expected \"h_over_l\" (SWIFT's eta "
            "is a code's setting: \"code\": {\"name\": \"swift\", \"eta\": ...})");
}

// Read as numbers and strings, checked by the relax request's own checks, named by pointer.
StudyRelax read_relax(const JsonNode& node)
{
    refuse_old_eta(node);
    node.expect_keys(declared_study_keys("relax")); // the block is a front end of `relax`: its keys are the rows'
    StudyRelax r;
    r.json_path = node.path();
    r.kernel = node.at("kernel").string();
    if (node.find("nh") && node.find("h_over_l")) node.error("expected one of \"nh\" and \"h_over_l\"");
    auto source = [&](const char* key) { return ValueSource::json(node.file(), node.path() + "/" + key); };
    RelaxSources sources = relax_sources(FrontEnd::python);
    sources.smoothing = {source("h_over_l"), source("nh"), source("k"), source("support_per_h"), ValueSource{}};
    sources.steps = source("steps");
    auto number = [&](const char* key) {
        const auto n = declared_node(node, "relax", key);
        return n ? std::optional(n->number()) : std::nullopt;
    };
    r.smoothing =
        smoothing_spec({number("h_over_l"), number("nh"), std::nullopt, std::nullopt}, sources.smoothing, r.smoothing);
    if (auto steps = declared_number(node, "relax", "steps")) r.settings.steps = static_cast<int>(*steps);
    if (auto method = declared_node(node, "relax", "method"))
        r.settings.method = relax_method_of(method->string(), source("method"));
    check_relax_settings(r.settings, sources);
    return r;
}

// The source request's names for a source's keys: JSON pointers (`dim`: its dimension's key).
SourceSources sources_at(const JsonNode& node, const std::string& dim)
{
    auto at = [&](const std::string& key) { return ValueSource::json(node.file(), node.path() + key); };
    return {at("/size"),  at("/sigma"),           at("/count"), at(dim), at("/box"),
            at("/array"), at("/particle_radius"), at("/cell"),  ""};
}

// A lattice block: its size in cells, the cell, the disorder and the seed; returns its label.
std::string read_lattice_source(const JsonNode& node, const JsonNode& lattice, const std::filesystem::path& study_file,
                                ParticleSource& src)
{
    node.expect_keys({"lattice", "size", "cell", "sigma", "seed", "relax"});
    src.kind = SourceKind::lattice;
    src.spec = resolve_beside(lattice.string(), study_file, {".json"});
    const auto size = node.at("size");
    const std::size_t n = size.expect_array(2, 3);
    src.cell_counts = n;
    std::string cells;
    for (std::size_t a = 0; a < n; ++a) {
        src.block.cells[a] = size[a].integer_in(LLONG_MIN, LLONG_MAX);
        if (a) cells += 'x';
        cells += std::to_string(src.block.cells[a]);
    }
    if (auto sigma = node.find("sigma")) src.block.sigma = sigma->number();
    if (auto cell = node.find("cell")) {
        const std::string name = cell->string();
        if (name != "primitive" && name != "rectangular")
            cell->error("\"" + name + "\" is unknown, expected primitive or rectangular");
        src.block.rectangular = name == "rectangular";
    }
    src.block.seed = seed_of(node);
    return fmt::format("{}, {} {}cells, sigma = {:g} d", lattice.string(), cells,
                       src.block.rectangular ? "rectangular " : "", src.block.sigma);
}

// Poisson points: the dimension, the count, the seed and the box; returns its label.
std::string read_poisson_source(const JsonNode& node, const JsonNode& poisson, ParticleSource& src)
{
    node.expect_keys({"poisson", "count", "seed", "box", "relax"});
    src.kind = SourceKind::poisson;
    src.spec = "poisson";
    src.poisson.dimension = static_cast<int>(poisson.integer_in(INT_MIN, INT_MAX));
    src.poisson.count = static_cast<std::size_t>(node.at("count").integer_in(0, LLONG_MAX));
    src.poisson.seed = seed_of(node);
    if (auto box = node.find("box")) {
        const std::size_t n = box->expect_array(2, 3);
        for (std::size_t a = 0; a < n; ++a) src.poisson.box[static_cast<int>(a)] = (*box)[a].number();
        check_particle_source(src, sources_at(node, "/poisson"));
        if (n != static_cast<std::size_t>(src.poisson.dimension)) box->error("expected one side per dimension");
    }
    return fmt::format("poisson, {}D, {} particles", src.poisson.dimension, src.poisson.count);
}

// A particle file beside the study: its box, array and dimension; returns its label (the name).
std::string read_file_source(const JsonNode& node, const std::filesystem::path& study_file, ParticleSource& src)
{
    node.expect_keys({"file", "box", "array", "dim", "relax"});
    src.kind = SourceKind::file;
    const auto name = node.at("file").string();
    src.spec = resolve_beside(name, study_file, {".h5", ".hdf5", ".csv", ".vtk"});
    if (auto box = node.find("box")) {
        const std::size_t n = box->expect_array(2, 3);
        Eigen::Vector3d sides(1, 1, 1);
        for (std::size_t a = 0; a < n; ++a) sides[static_cast<int>(a)] = (*box)[a].number();
        src.box = sides;
    }
    if (auto array = node.find("array")) src.file.array = array->string();
    if (auto dim = node.find("dim")) src.file.dimension = static_cast<int>(dim->integer_in(INT_MIN, INT_MAX));
    return name;
}

StudyParticleSource read_source(const JsonNode& node, const std::filesystem::path& study_file)
{
    node.expect_object();
    const int kinds = !!node.find("lattice") + !!node.find("poisson") + !!node.find("file");
    if (kinds != 1) node.error("expected one of \"lattice\", \"poisson\" and \"file\"");
    StudyParticleSource s;
    s.json_path = node.path();
    auto& src = s.source;
    if (auto lattice = node.find("lattice")) s.label = read_lattice_source(node, *lattice, study_file, src);
    else if (auto poisson = node.find("poisson")) s.label = read_poisson_source(node, *poisson, src);
    else s.label = read_file_source(node, study_file, src);
    check_particle_source(src, sources_at(node, src.kind == SourceKind::poisson ? "/poisson" : "/dim"));
    if (auto relax = node.find("relax")) {
        s.relax = read_relax(*relax);
        s.label += fmt::format(", relaxed ({}, {} = {:g}, {} steps)", s.relax->kernel,
                               s.relax->smoothing.rule == SmoothingRule::nh ? "N_H" : "h/l", s.relax->smoothing.value,
                               s.relax->settings.steps);
    }
    return s;
}

// {"name": "swift", "eta": 1.2348}: the code's parameter under its own name, or none.
StudyCode read_code(const JsonNode& node)
{
    node.expect_object();
    const auto& name = node.at("name");
    const auto& profile = code_profile(name.string(), ValueSource::json(name.file(), name.path()));
    node.expect_keys({"name", profile.parameter});
    StudyCode code{profile.name, std::nullopt, node.path()};
    if (auto value = node.find(profile.parameter)) {
        code.value = value->number();
        check_code_setting({code.name, *code.value}, {ValueSource::json(name.file(), name.path()),
                                                      ValueSource::json(value->file(), value->path())});
    }
    return code;
}

} // namespace

StudyParticles read_study_particles(const JsonNode& node, const std::filesystem::path& study_file)
{
    refuse_old_eta(node);
    node.expect_keys({"sources", "nh", "h_over_l", "code", "volume"});
    StudyParticles particles;
    particles.json_path = node.path();
    const auto sources = node.at("sources");
    const std::size_t n = sources.expect_array(1, 100);
    for (std::size_t i = 0; i < n; ++i) particles.sources.push_back(read_source(sources[i], study_file));
    if (!!node.find("nh") + !!node.find("h_over_l") + !!node.find("code") > 1)
        node.error("expected one of \"nh\", \"h_over_l\" and \"code\"");
    if (auto code = node.find("code")) particles.code = read_code(*code);
    if (auto range = node.find("nh") ? node.find("nh") : node.find("h_over_l")) {
        range->expect_keys({"min", "max", "steps"});
        const auto steps = range->find("steps");
        particles.sweep =
            checked_sweep(node.find("nh") ? SmoothingRule::nh : SmoothingRule::eta, range->at("min").number(),
                          range->at("max").number(), steps ? static_cast<int>(steps->integer_in(INT_MIN, INT_MAX)) : 9,
                          ValueSource::json(range->file(), range->path()),
                          ValueSource::json(range->file(), range->path() + "/steps"));
    }
    if (auto volume = node.find("volume")) {
        try {
            particles.volume = parse_volume_model(volume->string());
        } catch (const Error& e) {
            volume->error("expected \"uniform\", \"file\" or \"voronoi\"");
        }
    }
    return particles;
}

double study_particle_evaluations(const StudyParticles& particles)
{
    double total = 0;
    for (const auto& s : particles.sources) {
        double count = 1e6; // a file's size is known only once it is read
        if (s.source.kind == SourceKind::poisson) count = static_cast<double>(s.source.poisson.count);
        if (s.source.kind == SourceKind::lattice)
            count = double(s.source.block.cells[0]) * double(s.source.block.cells[1]) * double(s.source.block.cells[2]);
        // A code that solves h with the density takes a few passes of it (about 7 on a Poisson set).
        total += count * (particles.code ? 8 : particles.sweep.steps + 1);
    }
    return total;
}

} // namespace sphkern
