#include "particles/formats/particle_writers.hpp"
#include "particles/formats/phantom_dump_writer.hpp"

#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/chunked_writer.hpp"

#include <fmt/format.h>

#include <iterator>
#include <memory>
#include <ostream>

namespace sphkern {

void require_rectangular_box(const ParticleSet& set, const std::string& what)
{
    if (!set.box) fail_input(fmt::format("{}: {} needs a periodic box", set.name, what));
    const Eigen::Matrix3d& e = set.box->edges;
    const double off = e(0, 1) * e(0, 1) + e(0, 2) * e(0, 2) + e(1, 0) * e(1, 0) + e(1, 2) * e(1, 2) +
                       (set.dimension == 3 ? e(2, 0) * e(2, 0) + e(2, 1) * e(2, 1) : 0.0);
    if (off > 1e-24 * e.squaredNorm())
        fail_input(fmt::format("{}: the periodic box is a parallelepiped, not a rectangular box; {} stores three sides "
                               "(a block of a lattice's rectangular cell, poisson or a file with a rectangular box)",
                               set.name, what));
}

namespace {

void check_output(const ParticleSet& set, const ParticleOutput& output, const std::string& what)
{
    require_rectangular_box(set, what);
    if (output.h.size() != set.size()) throw std::logic_error("a particle file needs one h per particle");
}

} // namespace

void write_csv_particles(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output,
                         int threads)
{
    check_output(set, output, "a CSV particle file");
    const Eigen::Matrix3d& e = set.box->edges;
    const bool three = set.dimension == 3;
    write_file_atomically(file, [&](std::ostream& stream) {
        ChunkedWriter out(stream);
        out.print("# periodic box {:.17g} {:.17g}{}; support radius = {:.17g} h\n", e(0, 0), e(1, 1),
                  three ? fmt::format(" {:.17g}", e(2, 2)) : std::string(), output.support_per_h);
        out.text(three ? "x,y,z,h,m\n" : "x,y,h,m\n");
        out.rows(set.size(), worker_threads(threads), [&](fmt::memory_buffer& row, std::size_t i) {
            if (three)
                fmt::format_to(std::back_inserter(row), "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", set.x[i], set.y[i],
                               set.z[i], output.h[i], output.mass);
            else
                fmt::format_to(std::back_inserter(row), "{:.17g},{:.17g},{:.17g},{:.17g}\n", set.x[i], set.y[i],
                               output.h[i], output.mass);
        });
    });
}

void check_particle_output_name(const std::filesystem::path& file, ParticleLayout layout)
{
    const std::string ext = file.extension().string();
    const bool hdf5 = ext == ".h5" || ext == ".hdf5";
    if (layout == ParticleLayout::phantom && hdf5)
        throw Error(ExitCode::usage, file.string() +
                                         ": Phantom starts from its own full dumps, not HDF5; expected a "
                                         "name without .h5 or .hdf5 (NAME_00000.tmp) or one ending in .csv");
    if (layout != ParticleLayout::phantom && !hdf5 && ext != ".csv")
        throw Error(ExitCode::usage, file.string() + ": expected a name ending in .h5, .hdf5 or .csv");
}

void write_particle_file(const std::filesystem::path& file, const ParticleSet& set, const ParticleOutput& output,
                         int threads)
{
    check_particle_output_name(file, output.layout);
    const std::string ext = file.extension().string();
    if (ext == ".csv") write_csv_particles(file, set, output, threads);
    else if (output.layout == ParticleLayout::phantom) write_phantom_dump(file, set, output);
    else write_hdf5_particles(file, set, output);
}

} // namespace sphkern
