// HDF5 particle files: SWIFT and GADGET snapshots and initial conditions (/Header,
// /PartType0; formats/snapshot_rows) and PySPH output (/particles/<array>/arrays/<property>).
#include "codes/swift/swift_kernels.hpp"
#include "particles/formats/hdf5_file.hpp"
#include "particles/formats/particle_arrays.hpp"
#include "particles/formats/particle_files.hpp"
#include "particles/formats/snapshot_rows.hpp"

#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/text/printable_text.hpp"
#include "support/text/setting_names.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <regex>

namespace sphkern {

namespace {

using namespace hdf5;

// The names of the particle arrays under /particles, in the file's name order.
std::vector<std::string> pysph_array_names(const File& f)
{
    std::vector<std::string> names;
    Handle group(H5Gopen2(f.id, "/particles", f.group_access), H5Gclose);
    f.check_links();
    H5G_info_t info{};
    H5Gget_info(group.get(), &info);
    for (hsize_t i = 0; i < info.nlinks && i < 1000; ++i) {
        // A name of any length: its size asked first.
        const ssize_t length = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, f.links);
        if (length <= 0) fail_input(fmt::format("{}: the name of particle array {} cannot be read", f.name, i));
        std::string name(static_cast<std::size_t>(length) + 1, '\0');
        H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), f.links);
        name.resize(static_cast<std::size_t>(length));
        names.push_back(std::move(name));
    }
    if (names.empty())
        fail_input(fmt::format("{}: /particles holds no particle array; expected /particles/<array>/arrays/x, y[, z]",
                               f.name));
    return names;
}

// The arrays asked for (default: the only one, or "fluid"), each one the file has.
std::vector<std::string> chosen_pysph_arrays(const File& f, const std::string& requested)
{
    const auto names = pysph_array_names(f);
    std::string listed;
    for (const auto& n : names) listed += (listed.empty() ? "" : ", ") + n;
    if (const std::string problem = particle_array_list_problem(requested); !problem.empty())
        fail_input(fmt::format("{}: the array list \"{}\": {}", f.name, requested, problem));
    auto chosen = particle_array_names(requested);
    if (chosen.empty()) {
        if (names.size() == 1) chosen = names;
        else if (std::find(names.begin(), names.end(), "fluid") != names.end()) chosen = {"fluid"};
        else
            fail_input(fmt::format("{}: several particle arrays ({}); choose one with {} NAME", f.name, listed,
                                   setting_named("array")));
    }
    for (const auto& array : chosen)
        if (std::find(names.begin(), names.end(), array) == names.end())
            fail_input(fmt::format("{}: no particle array \"{}\"; the file has {}", f.name, array, listed));
    return chosen;
}

// One array's x, y, z, h, m and rho (each of the last four empty where the file has none).
ParticleSet read_pysph_array(const File& f, const std::string& array)
{
    const std::string base = "/particles/" + array + "/arrays/";
    if (!f.exists(base + "x") || !f.exists(base + "y"))
        fail_input(fmt::format("{}: {}x and {}y are missing; expected PySPH arrays x, y[, z][, h][, m][, rho]", f.name,
                               base, base));
    std::vector<hsize_t> shape;
    ParticleSet set;
    set.name = f.name;
    set.x = f.dataset(base + "x", shape);
    const std::size_t n = set.x.size();
    set.y = f.column(base + "y", n);
    // PySPH's dump writes a property it was not asked to output as an empty dataset (its
    // attribute "stored" false): absent, as if it were not in the file.
    auto optional_column = [&](const char* p) {
        const std::string path = base + p;
        if (!f.exists(path) || (n > 0 && f.rows(path) == 0)) return ParticleValues{};
        return f.column(path, n);
    };
    set.z = optional_column("z");
    if (set.z.empty()) set.z.assign(n, 0.0);
    set.h = optional_column("h");
    set.mass = optional_column("m");
    set.density = optional_column("rho");
    return set;
}

// The neighbours-only arrays' particles after the measured ones. A property the first array
// has must be in every array (each particle needs it); one it lacks is left out of all.
void append_pysph_array(ParticleSet& set, ParticleSet&& more, const std::string& first, const std::string& array)
{
    const std::pair<ParticleValues*, ParticleValues*> columns[] = {{&set.h, &more.h},
                                                                   {&set.mass, &more.mass},
                                                                   {&set.density, &more.density}};
    const char* names[] = {"h", "m", "rho"};
    for (std::size_t c = 0; c < 3; ++c)
        if (!columns[c].first->empty() && columns[c].second->empty())
            fail_input(
                fmt::format("{}: particle array \"{}\" has no {}, which \"{}\" has; expected it in every array read",
                            set.name, array, names[c], first));
    for (const auto& [whole, piece] : columns)
        if (!whole->empty()) whole->insert(whole->end(), piece->begin(), piece->end());
    for (const auto& [whole, piece] :
         {std::pair{&set.x, &more.x}, std::pair{&set.y, &more.y}, std::pair{&set.z, &more.z}})
        whole->insert(whole->end(), piece->begin(), piece->end());
    set.neighbours_only += more.size();
}

ParticleSet read_pysph(const File& f, const std::string& requested)
{
    const auto arrays = chosen_pysph_arrays(f, requested);
    ParticleSet set = read_pysph_array(f, arrays.front());
    if (set.size() == 0)
        fail_input(fmt::format("{}: particle array \"{}\" has no particles (PySPH's dump of an empty array); expected "
                               "the array to measure",
                               f.name, arrays.front()));
    set.arrays.emplace_back(arrays.front(), 0);
    for (std::size_t a = 1; a < arrays.size(); ++a) {
        ParticleSet more = read_pysph_array(f, arrays[a]);
        if (more.size() == 0) continue; // an empty wall adds no neighbour, whatever properties it stores
        set.arrays.emplace_back(arrays[a], set.size());
        append_pysph_array(set, std::move(more), arrays.front(), arrays[a]);
    }
    // PySPH keeps z (zero) for 2D runs.
    const bool flat = std::all_of(set.z.begin(), set.z.end(), [](double z) { return z == 0; });
    set.dimension = flat ? 2 : 3;
    if (flat) set.gravity = Eigen::Vector3d(0, -1, 0);
    return set;
}

} // namespace

ParticleSet read_hdf5_particles(const std::filesystem::path& file, const ParticleFileOptions& options)
{
    silence_hdf5();
    const std::string name = file.string();
    std::error_code ec;
    // A snapshot named by its base (snap.hdf5 for snap.0.hdf5 ...): its parts are named instead.
    const std::filesystem::path first = file.parent_path() / (file.stem().string() + ".0" + file.extension().string());
    if (!std::filesystem::exists(file, ec) && std::filesystem::is_regular_file(first, ec))
        fail_missing(fmt::format("{}: no such file; the snapshot is in parts: name one of them, such as {}", name,
                                 first.string()));
    if (!std::filesystem::exists(file, ec)) fail_missing(name + ": no such file");
    const OpenFile named(file);
    const File& f = named.file();
    std::vector<std::string> inputs;
    ParticleSet set;
    if (f.exists("/PartType0")) {
        if (!options.array.empty())
            throw Error(ExitCode::usage,
                        fmt::format("{} {}: names PySPH's particle arrays; {} is a SWIFT or GADGET snapshot, "
                                    "whose gas (PartType0) is the set",
                                    setting_named("array"), options.array, name));
        if (!f.exists("/PartType0/Coordinates"))
            fail_input(name + ": /PartType0/Coordinates is missing; expected a SWIFT or GADGET snapshot");
        const SnapshotRows snapshot(file);
        // The budget is checked against the declared total before anything is read.
        if (snapshot.size() > max_particles())
            fail_input(
                fmt::format("{}: /PartType0/Coordinates declares {} particles{} ({:.4g} bytes for the particles); over "
                            "the {} particles ({:.4g} bytes) the memory budget of {:.4g} bytes holds ({})",
                            name, snapshot.size(),
                            snapshot.parts() > 1 ? fmt::format(" in {} parts", snapshot.parts()) : std::string(),
                            static_cast<double>(snapshot.size()) * bytes_per_particle, max_particles(),
                            static_cast<double>(max_particles()) * bytes_per_particle,
                            static_cast<double>(memory_limit_bytes()), setting_named("memory_limit")));
        set = snapshot.rows(0, snapshot.size());
        inputs = snapshot.sample().linked_files;
    } else if (f.exists("/particles")) {
        set = read_pysph(f, options.array);
        // PySPH's dump keeps the solver's time as the attribute t of /solver_data.
        if (const auto t = f.attribute("/solver_data", "t"); !t.empty()) set.time = t[0];
    } else {
        fail_input(name + ": neither /PartType0 (SWIFT, GADGET) nor /particles (PySPH); expected a particle snapshot");
    }
    inputs.insert(inputs.end(), named.linked_files().begin(), named.linked_files().end());
    std::sort(inputs.begin(), inputs.end());
    inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
    set.linked_files = std::move(inputs);
    return set;
}

} // namespace sphkern