// The command-line options that name a particle set (a lattice block, poisson or a file),
// shared by `particles` and `relax`.
#pragma once

#include "cli/options.hpp"
#include "kernels/kernel.hpp"
#include "particles/sources/particle_source.hpp"
#include "support/io/sha256.hpp"

#include <nlohmann/json_fwd.hpp>

#include <memory>

#include <optional>
#include <string>

namespace sphkern::cli {

struct SourceOptions {
    std::string source, size, box, array, cell;
    double sigma = 0;
    unsigned long long seed = 0;
    std::optional<unsigned long long> count;
    std::optional<int> dim;
    std::optional<double> particle_radius;
};

void add_source_options(Command command, SourceOptions& options);

// Error(usage) for options that do not fit the kind of source (their values are checked by
// the source request, requests/source_request.hpp).
ParticleSource source_of(const SourceOptions& options);

// The kernel, the lattice and the source as given, and a file's SHA-256: enough to run it again.
// A file source's SHA-256, started now on a thread of its own (none for a lattice or Poisson
// set), for source_inputs: the command's work hides the seconds a large file takes.
std::unique_ptr<FileDigest> start_source_digest(const SourceOptions& options);
nlohmann::json source_inputs(const SourceOptions& options, const Kernel& kernel, FileDigest* digest = nullptr);

} // namespace sphkern::cli
