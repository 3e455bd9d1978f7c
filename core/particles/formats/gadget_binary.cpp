// GADGET-2's own binary snapshots and initial conditions (SnapFormat 1 and 2, either byte order),
// in one file or in the parts BASE.0, BASE.1, ... of a snapshot written as several: its gas
// particles (type 0) with their masses and, where stored, density and smoothing length (HSML,
// GADGET's support radius). The layout is that of GADGET-2's io.c write_file and read_ic.c
// read_file; share/docs/particle-formats.md describes it.
#include "particles/formats/gadget_records.hpp"
#include "particles/formats/particle_files.hpp"

#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <regex>
#include <tuple>

namespace sphkern {

namespace {

constexpr int types = 6;

// struct io_header (allvars.h): the fields sphkern reads.
struct GadgetHeader {
    std::array<std::int32_t, types> npart{};          // in this file
    std::array<double, types> mass{};                 // the MassTable: 0 where the MASS block holds the masses
    std::array<std::uint32_t, types> total{}, high{}; // npartTotal and npartTotalHighWord
    std::int32_t num_files = 0;
    double time = 0, box = 0;

    std::uint64_t gas_total() const { return total[0] + (std::uint64_t{high[0]} << 32); }
};

// Byte offsets in the 256-byte header.
constexpr std::size_t npart_at = 0, mass_at = 24, time_at = 72, total_at = 96, num_files_at = 124, box_at = 128,
                      high_at = 168;

GadgetHeader read_header(const GadgetRecords& f)
{
    const GadgetRecord& record = f.blocks().front();
    if (record.bytes != 256)
        fail_input(fmt::format("{}: its header (record {}) is {} bytes; expected GADGET's 256", f.name(), record.number,
                               record.bytes));
    const auto bytes = f.bytes(record);
    GadgetHeader h;
    for (std::size_t t = 0; t < types; ++t) {
        h.npart[t] = static_cast<std::int32_t>(f.word(bytes, npart_at + 4 * t));
        h.mass[t] = f.real(bytes, mass_at + 8 * t);
        h.total[t] = f.word(bytes, total_at + 4 * t);
        h.high[t] = f.word(bytes, high_at + 4 * t);
        if (h.npart[t] < 0)
            fail_input(fmt::format("{}: its header's npart[{}] is {}; expected a number of particles", f.name(), t,
                                   h.npart[t]));
    }
    h.num_files = static_cast<std::int32_t>(f.word(bytes, num_files_at));
    h.box = f.real(bytes, box_at);
    h.time = f.real(bytes, time_at);
    if (!std::isfinite(h.mass[0]) || h.mass[0] < 0)
        fail_input(
            fmt::format("{}: its header's MassTable[0] is negative or not a finite number; expected the gas particles' "
                        "mass, or 0 where the MASS block holds them",
                        f.name()));
    if (!std::isfinite(h.box) || h.box < 0)
        fail_input(
            fmt::format("{}: its header's BoxSize is negative or not a finite number; expected the periodic box's "
                        "side, or 0 for none",
                        f.name()));
    return h;
}

// A block of one file: its record and the bytes of each value (4: float, 8: double).
struct Block {
    std::size_t index = 0; // in GadgetRecords::blocks()
    std::size_t width = 0;
};

// The blocks sphkern checks: what each holds per particle and for which particles.
enum class Holds { all, with_mass, gas };
struct BlockKind {
    const char* label;
    std::size_t values; // per particle
    Holds holds;
    bool real; // floating point (else IDs: ints or long longs)
};
constexpr BlockKind kinds[] = {{"POS", 3, Holds::all, true}, {"VEL", 3, Holds::all, true},
                               {"ID", 1, Holds::all, false}, {"MASS", 1, Holds::with_mass, true},
                               {"U", 1, Holds::gas, true},   {"RHO", 1, Holds::gas, true},
                               {"HSML", 1, Holds::gas, true}};

std::size_t particles_in(const GadgetHeader& h, Holds holds)
{
    std::size_t n = 0;
    for (std::size_t t = 0; t < types; ++t)
        if (holds == Holds::all || (holds == Holds::with_mass && h.mass[t] == 0) || (holds == Holds::gas && t == 0))
            n += static_cast<std::size_t>(h.npart[t]);
    return n;
}

const char* whose(Holds holds)
{
    return holds == Holds::all   ? "particles"
           : holds == Holds::gas ? "gas particles"
                                 : "particles of types with no MassTable entry";
}

// The width of a block's values from its length: GADGET-2 writes floats, other writers doubles.
Block checked_block(const GadgetRecords& f, std::size_t index, const BlockKind& kind, const GadgetHeader& h)
{
    const GadgetRecord& record = f.blocks()[index];
    const std::size_t n = particles_in(h, kind.holds), per = n * kind.values;
    if (n == 0 && record.bytes == 0) return {index, 4};
    for (const std::size_t width : {std::size_t{4}, std::size_t{8}})
        if (per > 0 && record.bytes == per * width) return {index, width};
    fail_input(fmt::format("{}: block {} (record {}) is {} bytes; expected {} or {} bytes per particle for {} {}",
                           f.name(), kind.label, record.number, record.bytes, 4 * kind.values, 8 * kind.values, n,
                           whose(kind.holds)));
}

// One file of the snapshot: its header and the blocks sphkern reads.
struct GadgetPart {
    GadgetRecords records;
    GadgetHeader header;
    std::optional<Block> pos, mass, rho, hsml;
};

// The first block of each kind sphkern reads.
void keep(GadgetPart& part, const BlockKind& kind, const Block& block)
{
    const std::string label = kind.label;
    std::optional<Block>* slot = label == "POS"    ? &part.pos
                                 : label == "MASS" ? &part.mass
                                 : label == "RHO"  ? &part.rho
                                 : label == "HSML" ? &part.hsml
                                                   : nullptr;
    if (slot && !*slot) *slot = block;
}

// SnapFormat 1: the blocks in write_file's order, each one written only where it holds particles;
// initial conditions end after U, later blocks (POT, ACCE, ...) are not read.
void find_blocks_in_order(GadgetPart& part)
{
    const auto& blocks = part.records.blocks();
    std::size_t next = 1;
    for (const BlockKind& kind : kinds) {
        if (particles_in(part.header, kind.holds) == 0) continue;
        if (next == blocks.size()) {
            if (kind.holds == Holds::gas) return;
            fail_input(fmt::format("{}: the file ends after record {}; expected block {} for {} {} (a truncated file?)",
                                   part.records.name(), blocks.back().number, kind.label,
                                   particles_in(part.header, kind.holds), whose(kind.holds)));
        }
        keep(part, kind, checked_block(part.records, next++, kind, part.header));
    }
}

// SnapFormat 2: the blocks by their labels; others (a code's own) are passed over.
void find_labelled_blocks(GadgetPart& part)
{
    const auto& blocks = part.records.blocks();
    for (std::size_t i = 1; i < blocks.size(); ++i)
        for (const BlockKind& kind : kinds)
            if (blocks[i].label == kind.label) keep(part, kind, checked_block(part.records, i, kind, part.header));
    const auto& h = part.header;
    const std::string& name = part.records.name();
    if (!part.pos && particles_in(h, Holds::all) > 0)
        fail_input(fmt::format("{}: no block labelled POS; expected the positions of its {} particles", name,
                               particles_in(h, Holds::all)));
    if (!part.mass && h.mass[0] == 0 && h.npart[0] > 0)
        fail_input(fmt::format(
            "{}: no block labelled MASS, and MassTable[0] is 0; expected the masses of its {} gas particles", name,
            h.npart[0]));
}

GadgetPart read_part(const std::filesystem::path& path)
{
    GadgetPart part{GadgetRecords(path), {}, {}, {}, {}, {}};
    part.header = read_header(part.records);
    if (part.records.format() == 1) find_blocks_in_order(part);
    else find_labelled_blocks(part);
    return part;
}

// Every part's header must be the first's where the snapshot's header is meant.
void check_same_header(const GadgetPart& first, const GadgetPart& part)
{
    const auto& a = first.header;
    const auto& b = part.header;
    const char* field = a.num_files != b.num_files ? "num_files"
                        : a.total != b.total       ? "npartTotal"
                        : a.high != b.high         ? "npartTotalHighWord"
                        : a.mass != b.mass         ? "MassTable"
                        : a.box != b.box           ? "BoxSize"
                                                   : nullptr;
    if (field)
        fail_input(fmt::format("{}: its header's {} differs from {}'s; expected the parts of one snapshot",
                               part.records.name(), field, first.records.name()));
}

// Parts with gas particles must all store what the first one does.
void check_same_blocks(const GadgetPart& first, const GadgetPart& part)
{
    for (const auto& [label, mine, theirs] : {std::tuple{"RHO", first.rho.has_value(), part.rho.has_value()},
                                              std::tuple{"HSML", first.hsml.has_value(), part.hsml.has_value()}})
        if (mine != theirs)
            fail_input(fmt::format("{}: block {} is {} where {} has it {}; expected the parts of one snapshot",
                                   part.records.name(), label, theirs ? "present" : "missing", first.records.name(),
                                   mine ? "present" : "missing"));
}

// The files of the snapshot `file` names: itself, or the parts BASE.0 ... of the snapshot it is
// a part of (named by any part, or by BASE where BASE.0 exists, as GADGET-2's find_files does).
std::vector<GadgetPart> read_parts(const std::filesystem::path& file)
{
    std::error_code ec;
    const std::filesystem::path zero = file.string() + ".0";
    const bool by_base = !std::filesystem::exists(file, ec) && std::filesystem::is_regular_file(zero, ec);
    std::vector<GadgetPart> parts;
    parts.push_back(read_part(by_base ? zero : file));
    const auto& h = parts.front().header;
    if (h.num_files <= 1) return parts;
    static const std::regex numbered(R"((.*)\.(\d+))");
    std::smatch m;
    const std::string named = parts.front().records.name();
    std::string base;
    if (by_base) base = file.string();
    else if (std::regex_match(named, m, numbered)) base = m[1].str();
    else if (static_cast<std::uint64_t>(h.npart[0]) == h.gas_total())
        return parts; // one file holding every gas particle
    else
        fail_input(fmt::format(
            "{}: one of {} files of a snapshot (its header's num_files), but not named BASE.K; expected the "
            "parts' own names",
            named, h.num_files));
    if (h.num_files > 100000)
        fail_input(fmt::format("{}: its header's num_files is {}; expected a number of files", named, h.num_files));
    std::vector<GadgetPart> all;
    for (int k = 0; k < h.num_files; ++k) {
        const std::filesystem::path path = fmt::format("{}.{}", base, k);
        if (path.string() == named) {
            all.push_back(std::move(parts.front()));
            continue;
        }
        if (!std::filesystem::is_regular_file(path, ec))
            fail_input(fmt::format("{}: part {} of the snapshot's {} files, {}, {}; expected every part", named, k,
                                   h.num_files, path.string(),
                                   std::filesystem::is_directory(path, ec) ? "is a folder" : "does not exist"));
        all.push_back(read_part(path));
    }
    const GadgetPart* with_gas = nullptr;
    std::uint64_t gas = 0;
    for (const auto& part : all) {
        check_same_header(all.front(), part);
        gas += static_cast<std::uint64_t>(part.header.npart[0]);
        if (part.header.npart[0] == 0) continue;
        if (with_gas) check_same_blocks(*with_gas, part);
        else with_gas = &part;
    }
    if (gas != all.front().header.gas_total())
        fail_input(fmt::format(
            "{}: the snapshot's {} files hold {} gas particles but their headers' npartTotal[0] declares {}; "
            "expected the parts of one snapshot",
            named, all.size(), gas, all.front().header.gas_total()));
    return all;
}

// One part's gas particles appended to the set.
void append_part(const GadgetPart& part, ParticleSet& set)
{
    const std::size_t n = static_cast<std::size_t>(part.header.npart[0]);
    if (n == 0) return;
    const auto& f = part.records;
    // Gas particles come first in every block (write_file writes the types in order).
    const auto xyz = f.reals(f.blocks()[part.pos->index], 0, 3 * n, part.pos->width);
    for (std::size_t i = 0; i < n; ++i)
        set.x.push_back(xyz[3 * i]), set.y.push_back(xyz[3 * i + 1]), set.z.push_back(xyz[3 * i + 2]);
    auto append = [&](const std::optional<Block>& block, ParticleValues& into) {
        if (!block) return;
        const auto values = f.reals(f.blocks()[block->index], 0, n, block->width);
        into.insert(into.end(), values.begin(), values.end());
    };
    if (part.header.mass[0] > 0) set.mass.resize(set.mass.size() + n, part.header.mass[0]);
    else append(part.mass, set.mass);
    append(part.rho, set.density), append(part.hsml, set.h);
}

} // namespace

ParticleSet read_gadget_binary_particles(const std::filesystem::path& file, const ParticleFileOptions&)
{
    const auto parts = read_parts(file);
    const GadgetHeader& h = parts.front().header;
    std::uint64_t gas = 0;
    for (const auto& part : parts) gas += static_cast<std::uint64_t>(part.header.npart[0]);
    if (gas == 0)
        fail_input(fmt::format("{}: no gas particles (npart[0] is 0); expected GADGET's SPH particles, type 0",
                               file.string()));
    if (gas > max_particles())
        fail_input(
            fmt::format("{}: its header declares {} gas particles{} ({:.4g} bytes for the particles); over the memory "
                        "budget of {:.4g} bytes ({})",
                        file.string(), gas,
                        parts.size() > 1 ? fmt::format(" in {} parts", parts.size()) : std::string(),
                        static_cast<double>(gas) * bytes_per_particle, static_cast<double>(memory_limit_bytes()),
                        setting_named("memory_limit")));
    ParticleSet set;
    set.name = file.string();
    for (ParticleValues* column : {&set.x, &set.y, &set.z}) column->reserve(gas);
    for (const auto& part : parts) append_part(part, set);
    if (h.box > 0) {
        PeriodicBox box;
        box.edges = Eigen::Matrix3d::Identity() * h.box;
        set.box = box;
    }
    if (std::isfinite(h.time)) set.time = h.time;
    // GADGET's HSML is the radius where its kernel reaches zero.
    set.support_per_h = 1;
    if (parts.size() > 1)
        for (const auto& part : parts)
            set.linked_files.push_back(std::filesystem::path(part.records.name()).lexically_normal().string());
    std::sort(set.linked_files.begin(), set.linked_files.end());
    return set;
}

} // namespace sphkern
