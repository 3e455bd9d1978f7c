// A periodic particle lattice: primitive vectors, a motif of sites, a default gravity
// direction and named volume coefficients, rescaled so that the nearest-neighbour
// distance is d = 1.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

struct VolumeCoefficient {
    std::string name;
    double value;
    std::string origin; // "computed" or the file it came from
};

struct Lattice {
    std::string name;
    std::string title;
    std::string file;
    int dimension = 0;
    Eigen::Matrix3d basis;              // columns are the primitive vectors; in 2D the third is e_z
    std::vector<Eigen::Vector3d> motif; // fractional coordinates in [0, 1)
    Eigen::Vector3d gravity;            // unit vector pointing down
    double file_nearest_distance = 1;   // d in the file's own units, before the rescaling
    std::vector<VolumeCoefficient> volume_coefficients;

    int sites() const { return static_cast<int>(motif.size()); }
    double volume_per_site() const; // |det basis| / sites, in units of d^D

    // A named coefficient or a plain positive number; throws Error(input) otherwise.
    double volume_coefficient(const std::string& name_or_number) const;
};

// Reads and validates a lattice file (the format is in the README).
Lattice read_lattice(const std::filesystem::path& file);

// Validates a parsed lattice document; `file` names it in errors.
Lattice parse_lattice(const nlohmann::json& document, const std::string& file);

// A shipped lattice by name, or a lattice file by path (a spec with '/' or ending in .json).
Lattice load_lattice(const std::string& spec);

// Names of the shipped lattices, sorted.
std::vector<std::string> shipped_lattice_names();

} // namespace sphkern
