// Phantom's dumps (full and small, real*8 or real*4, either byte order): its gas particles with
// the gas particle mass of the header and Phantom's smoothing length h. The layout is that of
// Phantom's dump_utils (open_dumpfile_w, write_header, write_array, write_block_header) as
// readwrite_dumps' write_fulldump uses it; share/docs/particle-formats.md describes it.
#include "particles/formats/particle_files.hpp"
#include "particles/formats/phantom_records.hpp"

#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace sphkern {

namespace phantom {

namespace {

// The records in file order, taken one at a time; the end of the file names what was expected.
class Cursor {
public:
    explicit Cursor(const PhantomRecords& f) : f_(f) {}
    const PhantomRecord& take(const std::string& what)
    {
        const auto& all = f_.records();
        if (next_ == all.size())
            fail_input(fmt::format("{}: the file ends after record {}; expected {} (a truncated file?)", f_.name(),
                                   all.empty() ? 0 : all.back().number, what));
        return all[next_++];
    }
    // A record that must be `bytes` long: its contents.
    std::vector<char> take(const std::string& what, std::uint64_t bytes)
    {
        const auto& record = take(what);
        if (record.bytes != bytes)
            fail_input(fmt::format("{}: record {} ({}) is {} bytes; expected {}", f_.name(), record.number, what,
                                   record.bytes, bytes));
        return f_.bytes(record);
    }

private:
    const PhantomRecords& f_;
    std::size_t next_ = 0;
};

// The header's single values (write_header): each tag's first value, as Phantom's extract reads it.
struct Entry {
    std::string tag;
    int type = 0;
    double real = 0;
    std::int64_t integer = 0;
};

struct Header {
    std::vector<Entry> entries;

    const Entry* find(const std::string& tag, bool real) const
    {
        for (const auto& e : entries)
            if (e.tag == tag && is_real(e.type) == real) return &e;
        return nullptr;
    }
    std::optional<double> real(const std::string& tag) const
    {
        const Entry* e = find(tag, true);
        return e ? std::optional<double>(e->real) : std::nullopt;
    }
    std::optional<std::int64_t> integer(const std::string& tag) const
    {
        const Entry* e = find(tag, false);
        return e ? std::optional<std::int64_t>(e->integer) : std::nullopt;
    }
};

// The first record: int1, a default real (int2 as a real), int2, the format version, int1o.
// Its length tells the default real's width.
std::size_t read_magic(const PhantomRecords& f, Cursor& c)
{
    const auto& record = c.take("Phantom's magic numbers");
    const std::size_t real_width = record.bytes == 24 ? 8 : 4;
    const auto bytes = f.bytes(record);
    const char* p = bytes.data() + 4 + real_width;
    const auto int2 = f.integer(p, 4), version = f.integer(p + 4, 4), int1o = f.integer(p + 8, 4);
    if ((int2 != magic_real && int2 != magic_real_old) || int1o != magic_old)
        fail_input(fmt::format("{}: record 1 holds {} and {} where Phantom's magic numbers 060878 and 690706 stand; "
                               "expected a dump with a {}-byte real and 4-byte integers",
                               f.name(), int2, int1o, real_width));
    if (version != format_version && version != magic_old)
        fail_input(fmt::format("{}: record 1 gives the dump format version {}; expected 1", f.name(), version));
    return real_width;
}

// The file id: "F" (full dump) or "S" (small dump), then "T" for the tagged format.
void read_fileid(const PhantomRecords& f, Cursor& c)
{
    const auto& record = c.take("the file id");
    const auto bytes = f.bytes(record);
    const std::string id = tag_of(bytes.data(), std::min<std::size_t>(bytes.size(), lenid));
    if (id.size() < 2 || (id[0] != 'F' && id[0] != 'S') || (id[1] != 'T' && id[1] != 't'))
        fail_input(
            fmt::format("{}: its file id (record {}) is \"{}\"; expected a tagged dump, \"FT:...\" or \"ST:...\" "
                        "(untagged sphNG dumps are not read)",
                        f.name(), record.number, id.substr(0, 20)));
}

Header read_header(const PhantomRecords& f, Cursor& c, std::size_t real_width)
{
    Header h;
    for (int type = 0; type < ntypes; ++type) {
        const std::string name = type_names[type];
        const auto count = f.integer(c.take("the number of " + name + " header values", 4).data(), 4);
        if (count <= 0) continue;
        const auto n = static_cast<std::uint64_t>(count);
        const auto tags = c.take(fmt::format("the tags of {} {} header values", n, name), n * lentag);
        const std::size_t w = width(type, real_width);
        const auto values = c.take(fmt::format("{} {} header values", n, name), n * w);
        for (std::size_t i = 0; i < n; ++i) {
            Entry e{tag_of(tags.data() + i * lentag, lentag), type, 0, 0};
            if (is_real(type)) e.real = f.real(values.data() + i * w, w);
            else e.integer = f.integer(values.data() + i * w, w);
            h.entries.push_back(e);
        }
    }
    return h;
}

// An array of the hydro block sphkern reads: its values' record and type.
struct Array {
    const PhantomRecord* record = nullptr;
    int type = 0;
};

// One MPI block's hydrodynamic particles and the arrays of them sphkern reads.
struct HydroBlock {
    std::uint64_t particles = 0;
    Array x, y, z, h, itype;
};

// Block b's headers (write_block_header): for each array length, its particles and how many
// arrays of each type it holds.
struct BlockHeaders {
    std::array<std::uint64_t, max_arraylengths> length{};
    std::array<std::array<std::int64_t, ntypes>, max_arraylengths> count{};
};
BlockHeaders read_block_headers(const PhantomRecords& f, Cursor& c, std::int64_t b, std::size_t arraylengths)
{
    BlockHeaders h;
    for (std::size_t j = 0; j < arraylengths; ++j) {
        const auto bytes = c.take(fmt::format("the header of block {}.{}", b, j + 1), 8 + 4 * ntypes);
        const auto n = f.integer(bytes.data(), 8);
        if (n < 0)
            fail_input(
                fmt::format("{}: block {}.{} declares {} particles; expected a number >= 0", f.name(), b, j + 1, n));
        h.length[j] = static_cast<std::uint64_t>(n);
        for (int t = 0; t < ntypes; ++t) {
            h.count[j][t] = f.integer(bytes.data() + 8 + 4 * t, 4);
            if (h.count[j][t] < 0)
                fail_input(fmt::format("{}: block {}.{} declares {} {} arrays; expected a number >= 0", f.name(), b,
                                       j + 1, h.count[j][t], type_names[t]));
        }
    }
    return h;
}

// Each MPI block: `arraylengths` block headers (write_block_header: an int*8 length and the
// count of arrays of each type), then for each array length, for each type, its arrays as a
// tag record and a values record. The first array length is the hydrodynamic particles'.
std::vector<HydroBlock> read_blocks(const PhantomRecords& f, Cursor& c, const Header& header, std::size_t real_width)
{
    const std::int64_t nblocks = header.integer("nblocks").value_or(1);
    const auto arrays = f.integer(c.take("the number of blocks", 4).data(), 4);
    if (nblocks < 1 || arrays < 1 || arrays % nblocks != 0 || arrays / nblocks > max_arraylengths)
        fail_input(fmt::format("{}: {} array blocks for the header's nblocks {}; expected 1 to {} a block", f.name(),
                               arrays, nblocks, max_arraylengths));
    const auto arraylengths = static_cast<std::size_t>(arrays / nblocks);
    std::vector<HydroBlock> blocks;
    for (std::int64_t b = 1; b <= nblocks; ++b) {
        const auto [length, count] = read_block_headers(f, c, b, arraylengths);
        HydroBlock hydro{length[0], {}, {}, {}, {}, {}};
        for (std::size_t j = 0; j < arraylengths; ++j)
            for (int t = 0; t < ntypes; ++t)
                for (std::int64_t a = 0; a < count[j][t]; ++a) {
                    const std::string what =
                        fmt::format("the tag of {} array {} of block {}.{}", type_names[t], a + 1, b, j + 1);
                    const auto tag = tag_of(c.take(what, lentag).data(), lentag);
                    const auto& values = c.take(fmt::format("array {} of block {}.{}", tag, b, j + 1));
                    const std::size_t w = width(t, real_width);
                    if (values.bytes != length[j] * w)
                        fail_input(
                            fmt::format("{}: array {} (record {}) of block {}.{} is {} bytes; expected {} ({}) for "
                                        "each of the block's {} particles",
                                        f.name(), tag, values.number, b, j + 1, values.bytes, w, type_names[t],
                                        length[j]));
                    if (j != 0) continue;
                    Array* slot = tag == "x"       ? &hydro.x
                                  : tag == "y"     ? &hydro.y
                                  : tag == "z"     ? &hydro.z
                                  : tag == "h"     ? &hydro.h
                                  : tag == "itype" ? &hydro.itype
                                                   : nullptr;
                    const bool fits = tag == "itype" ? !is_real(t) : is_real(t);
                    if (slot && !slot->record && fits) *slot = {&values, t};
                }
        if (hydro.particles > 0)
            for (const auto& [tag, array] : {std::pair{"x", hydro.x}, {"y", hydro.y}, {"z", hydro.z}})
                if (!array.record)
                    fail_input(
                        fmt::format("{}: block {} has no real array {}; expected the positions x, y, z of its {} "
                                    "particles",
                                    f.name(), b, tag, hydro.particles));
        blocks.push_back(hydro);
    }
    return blocks;
}

// The values of one array as doubles (reals) or integers.
std::vector<double> reals(const PhantomRecords& f, const Array& a, std::size_t real_width)
{
    const auto bytes = f.bytes(*a.record);
    const std::size_t w = width(a.type, real_width), n = bytes.size() / w;
    std::vector<double> values(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = f.real(bytes.data() + i * w, w);
    return values;
}

std::vector<std::int64_t> integers(const PhantomRecords& f, const Array& a, std::size_t real_width)
{
    const auto bytes = f.bytes(*a.record);
    const std::size_t w = width(a.type, real_width), n = bytes.size() / w;
    std::vector<std::int64_t> values(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = f.integer(bytes.data() + i * w, w);
    return values;
}

// Phantom writes the box's bounds only for a periodic build (readwrite_dumps_common's
// fill_header): where all six are there, the dump is of a periodic box.
std::optional<std::array<double, 6>> bounds(const Header& header)
{
    std::array<double, 6> b{};
    const char* tags[] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
    for (std::size_t i = 0; i < b.size(); ++i) {
        const auto v = header.real(tags[i]);
        if (!v) return std::nullopt;
        b[i] = *v;
    }
    return b;
}

} // namespace

} // namespace phantom

ParticleSet read_phantom_dump_particles(const std::filesystem::path& file, const ParticleFileOptions&)
{
    using namespace phantom;
    const PhantomRecords f(file);
    Cursor c(f);
    const std::size_t real_width = read_magic(f, c);
    read_fileid(f, c);
    const Header header = read_header(f, c, real_width);
    const auto mass = header.real("massoftype");
    if (!mass)
        fail_input(fmt::format("{}: its header has no massoftype; expected the gas particle mass, massoftype(1)",
                               file.string()));
    if (!std::isfinite(*mass) || *mass <= 0)
        fail_input(fmt::format("{}: its header's massoftype(1) is {}; expected the gas particles' mass, > 0",
                               file.string(), *mass));
    const auto blocks = read_blocks(f, c, header, real_width);
    std::uint64_t hydro = 0;
    for (const auto& b : blocks) hydro += b.particles;
    if (const auto total = header.integer("nparttot"); total && static_cast<std::uint64_t>(*total) != hydro)
        fail_input(fmt::format("{}: its blocks hold {} particles but the header's nparttot is {}; expected the same",
                               file.string(), hydro, *total));
    const std::uint64_t gas_bound =
        std::min<std::uint64_t>(hydro,
                                static_cast<std::uint64_t>(std::max<std::int64_t>(
                                    header.integer("npartoftype").value_or(static_cast<std::int64_t>(hydro)), 0)));
    if (gas_bound > max_particles())
        fail_input(fmt::format(
            "{}: its header declares {} gas particles ({:.4g} bytes for the particles); over the memory budget "
            "of {:.4g} bytes ({})",
            file.string(), gas_bound, static_cast<double>(gas_bound) * bytes_per_particle,
            static_cast<double>(memory_limit_bytes()), setting_named("memory_limit")));
    ParticleSet set;
    set.name = file.string();
    set.time = header.real("time");
    const bool with_h =
        std::all_of(blocks.begin(), blocks.end(), [](const HydroBlock& b) { return b.particles == 0 || b.h.record; });
    std::uint64_t row = 0;
    bool skipped = false;
    std::vector<std::uint64_t> rows;
    for (const auto& b : blocks) {
        if (b.particles == 0) continue;
        const auto x = reals(f, b.x, real_width), y = reals(f, b.y, real_width), z = reals(f, b.z, real_width);
        const auto h = with_h ? reals(f, b.h, real_width) : std::vector<double>();
        const auto type = b.itype.record ? integers(f, b.itype, real_width) : std::vector<std::int64_t>();
        for (std::size_t i = 0; i < b.particles; ++i, ++row) {
            // Only gas is SPH; an accreted particle keeps its row with h < 0 until the next compaction.
            if ((!type.empty() && type[i] != igas) || (with_h && h[i] <= 0)) {
                skipped = true;
                continue;
            }
            set.x.push_back(x[i]), set.y.push_back(y[i]), set.z.push_back(z[i]);
            if (with_h) set.h.push_back(h[i]);
            rows.push_back(row);
        }
    }
    if (set.x.empty())
        fail_input(
            fmt::format("{}: no gas particles (itype 1, h > 0) among its {} particles; expected Phantom's SPH gas",
                        file.string(), hydro));
    if (skipped) set.ids = std::move(rows);
    set.mass.assign(set.x.size(), *mass);
    if (const auto b = bounds(header); b && b->at(1) > b->at(0) && b->at(3) > b->at(2) && b->at(5) > b->at(4)) {
        PeriodicBox box;
        box.edges = Eigen::Vector3d(b->at(1) - b->at(0), b->at(3) - b->at(2), b->at(5) - b->at(4)).asDiagonal();
        set.box = box;
        // sphkern's boxes start at the origin: positions are taken from the box's lower corner.
        const std::array<double, 3> lower{b->at(0), b->at(2), b->at(4)};
        ParticleValues* columns[] = {&set.x, &set.y, &set.z};
        for (std::size_t d = 0; d < 3; ++d)
            if (lower[d] != 0)
                for (double& v : *columns[d]) v -= lower[d];
    }
    // Phantom's h is its kernel's support over radkern: --code phantom applies that convention.
    set.support_per_h = 0;
    return set;
}

} // namespace sphkern
