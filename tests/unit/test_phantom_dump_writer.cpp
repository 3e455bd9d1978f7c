// A Phantom full dump sphkern writes, read back by sphkern's own Phantom reader: the positions
// bit for bit, h as the real*4 Phantom writes, the mass and the box; and what cannot be a Phantom dump refused in one
// line.
#include "helpers.hpp"
#include "particles/formats/particle_files.hpp"
#include "particles/formats/phantom_dump_writer.hpp"
#include "particles/formats/phantom_records.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <random>
#include <unistd.h>

using namespace sphkern;

namespace {

// 300 particles anywhere in a 1 x 2 x 3 box, each with its own h (no two alike).
ParticleSet scattered_set()
{
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(0, 1);
    ParticleSet set;
    set.name = "scattered";
    PeriodicBox box;
    box.edges = Eigen::Vector3d(1, 2, 3).asDiagonal();
    set.box = box;
    for (int i = 0; i < 300; ++i) {
        set.x.push_back(unit(rng)), set.y.push_back(2 * unit(rng)), set.z.push_back(3 * unit(rng));
    }
    return set;
}

ParticleOutput dump_output(const ParticleSet& set)
{
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> spread(0.2, 0.3);
    ParticleOutput out;
    for (std::size_t i = 0; i < set.size(); ++i) out.h.push_back(spread(rng));
    out.mass = 6.0 / 300, out.density = 1, out.internal_energy = 0.9, out.hfact = 1.2;
    out.eos_gamma = 5.0 / 3, out.sound_speed = 1;
    out.layout = ParticleLayout::phantom;
    return out;
}

std::filesystem::path scratch()
{
    const auto dir = std::filesystem::temp_directory_path() / ("sphkern-phantom-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace

TEST_CASE("a written Phantom dump reads back: positions bit for bit, h as its real*4, the mass and the box")
{
    const auto dir = scratch();
    const ParticleSet set = scattered_set();
    const ParticleOutput out = dump_output(set);
    const auto file = dir / "glass_00000.tmp";
    write_particle_file(file, set, out);
    CHECK(is_phantom_dump(file));
    CHECK(particle_file_format(file) == ParticleFileFormat::phantom_dump);
    const ParticleSet back = read_particle_file(file, {});
    REQUIRE(back.size() == set.size());
    CHECK(back.dimension == 3);
    for (std::size_t i = 0; i < set.size(); ++i) {
        CAPTURE(i);
        // Bit for bit: == on doubles, and no id list (every particle is gas with h > 0).
        CHECK(std::memcmp(&back.x[i], &set.x[i], sizeof(double)) == 0);
        CHECK(std::memcmp(&back.y[i], &set.y[i], sizeof(double)) == 0);
        CHECK(std::memcmp(&back.z[i], &set.z[i], sizeof(double)) == 0);
        CHECK(back.h[i] == static_cast<double>(static_cast<float>(out.h[i]))); // write_fulldump's real*4 h
        CHECK(back.mass[i] == out.mass);
    }
    CHECK(back.ids.empty());
    REQUIRE(back.box);
    CHECK(back.box->edges == set.box->edges);
    std::filesystem::remove_all(dir);
}

TEST_CASE("a Phantom dump is a 3D set in a rectangular box with an HDF5-free name")
{
    const auto dir = scratch();
    ParticleSet set = scattered_set();
    const ParticleOutput out = dump_output(set);
    ParticleSet flat = set;
    flat.dimension = 2;
    auto [message, code] = test::refusal([&] { write_particle_file(dir / "flat_00000", flat, out); });
    CHECK(code == ExitCode::input);
    CHECK(message.find("flat_00000: a Phantom dump holds a 3D set; this set is 2D") != std::string::npos);
    ParticleSet free = set;
    free.box.reset();
    std::tie(message, code) = test::refusal([&] { write_particle_file(dir / "free_00000", free, out); });
    CHECK(code == ExitCode::input);
    CHECK(message.find("the Phantom dump " + (dir / "free_00000").string() + " needs a periodic box") !=
          std::string::npos);
    std::tie(message, code) = test::refusal([&] { write_particle_file(dir / "ic.hdf5", set, out); });
    CHECK(code == ExitCode::usage);
    CHECK(message.find("ic.hdf5: Phantom starts from its own full dumps, not HDF5") != std::string::npos);
    CHECK(!std::filesystem::exists(dir / "flat_00000"));
    CHECK(!std::filesystem::exists(dir / "free_00000"));
    CHECK(!std::filesystem::exists(dir / "ic.hdf5"));
    std::filesystem::remove_all(dir);
}
