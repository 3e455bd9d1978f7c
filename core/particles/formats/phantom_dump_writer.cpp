#include "particles/formats/phantom_dump_writer.hpp"
#include "particles/formats/phantom_records.hpp"

#include "support/error.hpp"
#include "support/io/atomic_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

namespace sphkern {

namespace phantom_writing {

namespace {

// One header value: its tag, its data type and the value (an integer type's is whole).
struct Value {
    std::string tag;
    int type = phantom::i_int;
    double value = 0;
};

// The bytes of `value` as a value of `type` (default integers and int*4: 4 bytes; int*8 and
// default reals: 8, a full dump of Phantom's usual double-precision build).
void append(std::string& bytes, int type, double value)
{
    char raw[8];
    std::size_t n = 8;
    if (type == phantom::i_int || type == phantom::i_int4) {
        const auto v = static_cast<std::int32_t>(value);
        std::memcpy(raw, &v, n = sizeof v);
    } else if (type == phantom::i_int8) {
        const auto v = static_cast<std::int64_t>(value);
        std::memcpy(raw, &v, sizeof v);
    } else {
        std::memcpy(raw, &value, sizeof value);
    }
    bytes.append(raw, n);
}

constexpr int maxtypes = 8; // config.F90's 7 + 2 maxdustlarge - 1 without dust

// An array of the header (one value per particle type): `first` for gas, 0 for the others.
void per_type(std::vector<Value>& v, const char* tag, int type, double first)
{
    for (int t = 1; t <= maxtypes; ++t) v.push_back({tag, type, t == phantom::igas ? first : 0});
}

// fill_header's integers, in its order within each type.
void integer_values(const ParticleSet& set, const ParticleOutput& output, std::vector<Value>& v)
{
    constexpr int idust = 7; // part.F90
    const auto n = static_cast<double>(set.size());
    // default integers
    v.push_back({"nparttot", phantom::i_int, n});
    v.push_back({"ntypes", phantom::i_int, maxtypes});
    per_type(v, "npartoftype", phantom::i_int, n);
    for (const auto& [tag, value] : {std::pair{"nblocks", 1},
                                     {"nptmass", 0},
                                     {"ndustlarge", 0},
                                     {"ndustsmall", 0},
                                     {"idust", idust},
                                     {"idtmax_n", 1},
                                     {"idtmax_frac", 0},
                                     {"idumpfile", 0},
                                     {"isink", 0}})
        v.push_back({tag, phantom::i_int, static_cast<double>(value)});
    // int*8: the counts again, for a run with more than 2^31 particles
    v.push_back({"nparttot", phantom::i_int8, n});
    v.push_back({"ntypes", phantom::i_int8, maxtypes});
    per_type(v, "npartoftype", phantom::i_int8, n);
    // int*4: Phantom reads ieos from its .in file, not from here; 2 is adiabatic, 1 isothermal.
    v.push_back({"iexternalforce", phantom::i_int4, 0});
    v.push_back({"ieos", phantom::i_int4, output.eos_gamma > 1 ? 2.0 : 1.0});
}

// fill_header's reals, in its order within each type.
void real_values(const ParticleSet& set, const ParticleOutput& output, std::vector<Value>& v)
{
    // default reals: the equation of state first (write_headeropts_eos), read back by
    // read_headeropts_eos: gamma, and RK2 = 3/2 polyk for the pressure at rest
    // P = polyk rho^gamma = rho0 c^2 / gamma (rho / rho0)^gamma (isothermal: polyk = c^2).
    const double gamma = output.eos_gamma, c = output.sound_speed, rho0 = output.density;
    const double polyk = c * c * std::pow(rho0, 1 - gamma) / gamma;
    for (const auto& [tag, value] : {std::pair{"gamma", gamma},
                                     {"RK2", 1.5 * polyk},
                                     {"polyk2", 0.0},
                                     {"qfacdisc", 0.75},
                                     {"qfacdisc2", 0.75},
                                     {"cs_min", 0.0},
                                     {"time", 0.0},
                                     {"dtmax", 0.0},
                                     {"rhozero", rho0},
                                     {"hfact", output.hfact},
                                     {"tolh", 1e-4},
                                     {"C_cour", 0.3},
                                     {"C_force", 0.25},
                                     {"alpha", 1.0},
                                     {"alphau", 1.0},
                                     {"alphaB", 1.0}})
        v.push_back({tag, phantom::i_real, value});
    per_type(v, "massoftype", phantom::i_real, output.mass);
    for (const char* tag : {"Bextx", "Bexty", "Bextz", "dum"}) v.push_back({tag, phantom::i_real, 0});
    // A periodic build reads the box here (unfill_rheader); sphkern's box starts at the origin.
    const Eigen::Matrix3d& e = set.box->edges;
    const char* bounds[] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d) {
        v.push_back({fmt::format("{}min", bounds[d]), phantom::i_real, 0});
        v.push_back({fmt::format("{}max", bounds[d]), phantom::i_real, e(d, d)});
    }
    // get_conserv = 1: Phantom takes the conserved totals at its first step.
    for (const auto& [tag, value] :
         {std::pair{"get_conserv", 1.0}, {"mtot_in", 0.0}, {"etot_in", 0.0}, {"angtot_in", 0.0}, {"totmom_in", 0.0}})
        v.push_back({tag, phantom::i_real, value});
    // real*8: code units of 1 (cm, g, s), and set_units_extra's field unit for them, sqrt(4 pi).
    for (const char* tag : {"udist", "umass", "utime"}) v.push_back({tag, phantom::i_real8, 1});
    v.push_back({"umagfd", phantom::i_real8, std::sqrt(4 * std::numbers::pi)});
}

// fill_header's values for a hydro run of gas alone, no dust, no MHD, no sinks, no external
// force, in its order within each type (an array repeats its tag, one value per element).
std::vector<Value> header_values(const ParticleSet& set, const ParticleOutput& output)
{
    std::vector<Value> v;
    integer_values(set, output, v);
    real_values(set, output, v);
    return v;
}

// write_header: for each type, the count, and where there are values their tags and values.
void write_header(PhantomRecordWriter& out, const std::vector<Value>& values)
{
    for (int type = 0; type < phantom::ntypes; ++type) {
        std::string tags, bytes;
        std::int32_t count = 0;
        for (const auto& v : values)
            if (v.type == type) {
                tags += phantom::padded(v.tag, phantom::lentag);
                append(bytes, type, v.value);
                ++count;
            }
        out.record(&count, sizeof count);
        if (count == 0) continue;
        out.record(tags);
        out.record(bytes);
    }
}

// One array of the hydro block: its tag, its type (int*8 or a default real) and its n values.
struct Array {
    std::string tag;
    int type = phantom::i_real;
    const void* values = nullptr;
};

// write_block_header's record for one array length: the int*8 number of rows and the count
// of its arrays of each type.
std::string block_header(std::int64_t rows, const std::vector<Array>& arrays)
{
    std::string bytes;
    append(bytes, phantom::i_int8, static_cast<double>(rows));
    for (int type = 0; type < phantom::ntypes; ++type) {
        std::int32_t count = 0;
        for (const auto& a : arrays) count += a.type == type;
        bytes.append(reinterpret_cast<const char*>(&count), sizeof count);
    }
    return bytes;
}

// The arrays by type, each as its tag and its values (4 bytes each for real*4, else 8).
void write_arrays(PhantomRecordWriter& out, const std::vector<Array>& arrays, std::size_t n)
{
    for (int type = 0; type < phantom::ntypes; ++type)
        for (const auto& a : arrays) {
            if (a.type != type) continue;
            out.record(phantom::padded(a.tag, phantom::lentag));
            out.record(a.values, n * (a.type == phantom::i_real4 ? 4 : 8));
        }
}

} // namespace

} // namespace phantom_writing

void write_phantom_dump(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output)
{
    const std::string name = file.string();
    if (set.dimension != 3)
        fail_input(fmt::format("{}: a Phantom dump holds a 3D set; this set is {}D", name, set.dimension));
    require_rectangular_box(set, "the Phantom dump " + name);
    if (output.h.size() != set.size()) throw std::logic_error("a Phantom dump needs one h per particle");
    // read_dump reads nparttot as a default (4-byte) integer too.
    if (set.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        fail_input(
            fmt::format("{}: {} particles; Phantom's header holds nparttot as a 4-byte integer, expected at most {}",
                        name, set.size(), std::numeric_limits<std::int32_t>::max()));
    const std::size_t n = set.size();
    std::vector<std::int64_t> iorig(n);
    for (std::size_t i = 0; i < n; ++i) iorig[i] = static_cast<std::int64_t>(i + 1); // Phantom's ids count from 1
    const std::vector<double> rest(n, 0.0), u(n, output.internal_energy);
    // write_fulldump writes h as real*4 (use_kind=4), whatever its default real; SPLASH builds
    // its density column from such an h.
    std::vector<float> h4(n);
    for (std::size_t i = 0; i < n; ++i) h4[i] = static_cast<float>(output.h[i]);
    // write_fulldump's order within each type: iorig; x, y, z, vx, vy, vz, u; then h (real*4).
    const std::vector<phantom_writing::Array> hydro{
        {"iorig", phantom::i_int8, iorig.data()}, {"x", phantom::i_real, set.x.data()},
        {"y", phantom::i_real, set.y.data()},     {"z", phantom::i_real, set.z.data()},
        {"vx", phantom::i_real, rest.data()},     {"vy", phantom::i_real, rest.data()},
        {"vz", phantom::i_real, rest.data()},     {"u", phantom::i_real, u.data()},
        {"h", phantom::i_real4, h4.data()}};
    write_file_atomically(file, [&](std::ostream& stream) {
        PhantomRecordWriter out(stream, name);
        // open_dumpfile_w: int1, int2 as a default real, int2, iversion, int1o; then the file id.
        std::string magic;
        phantom_writing::append(magic, phantom::i_int, phantom::magic);
        phantom_writing::append(magic, phantom::i_real, phantom::magic_real);
        phantom_writing::append(magic, phantom::i_int, phantom::magic_real);
        phantom_writing::append(magic, phantom::i_int, phantom::format_version);
        phantom_writing::append(magic, phantom::i_int, phantom::magic_old);
        out.record(magic);
        // "F" a full dump, "T" tagged; "Phantom" tells read_dump it is not sphNG's.
        out.record(phantom::padded(fmt::format("FT:Phantom:sphkern {} (hydro)", SPHKERN_VERSION), phantom::lenid));
        phantom_writing::write_header(out, phantom_writing::header_values(set, output));
        // One MPI block of two array lengths: the hydro particles and no sinks.
        const std::int32_t arraylengths = 2;
        out.record(&arraylengths, sizeof arraylengths);
        out.record(phantom_writing::block_header(static_cast<std::int64_t>(n), hydro));
        out.record(phantom_writing::block_header(0, {}));
        phantom_writing::write_arrays(out, hydro, n);
    });
}

} // namespace sphkern
