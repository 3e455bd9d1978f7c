#include "lattices/lattice.hpp"

#include "support/text/printable_text.hpp"

#include "lattices/lattice_points.hpp"
#include "lattices/numeric_inputs.hpp"
#include "support/error.hpp"
#include "support/io/file_spec.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/json_input.hpp"
#include "support/process/resource_errors.hpp"
#include "support/text/value_checks.hpp"

#include <Eigen/LU>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace sphkern {
namespace fs = std::filesystem;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double max_coordinate = 1e6;

Eigen::Vector3d read_vector(const JsonNode& node, int dimension, double limit)
{
    if (!node.is_array())
        node.error("expected an array of " + std::to_string(dimension) + " numbers, got " +
                   json_type_name(node.value()));
    if (node.size() != static_cast<std::size_t>(dimension))
        node.error("expected " + std::to_string(dimension) + " components (dimension is " + std::to_string(dimension) +
                   "), got " + std::to_string(node.size()));
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (int i = 0; i < dimension; ++i) v[i] = node[static_cast<std::size_t>(i)].number_in(-limit, limit);
    return v;
}

// The smallest distance between two lattice points, in the file's units.
double nearest_neighbour_distance(const Eigen::Matrix3d& basis, int dimension,
                                  const std::vector<Eigen::Vector3d>& motif)
{
    // A primitive vector of the reduced basis bounds the distance: search no further.
    const Eigen::Matrix3d reduced = reduce_basis(basis, dimension).first;
    double shortest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < dimension; ++i) shortest = std::min(shortest, reduced.col(i).norm());
    double nearest = shortest; // a primitive vector is itself a lattice translation
    for (int site = 0; site < static_cast<int>(motif.size()); ++site)
        for_each_lattice_point(basis, dimension, motif, site, shortest,
                               [&](const Eigen::Vector3d& x) { nearest = std::min(nearest, x.norm()); });
    return nearest;
}

std::string read_lattice_name(const JsonNode& root)
{
    auto node = root.at("name");
    std::string name = node.string();
    if (!is_identifier(name, "-")) node.error("expected a name of up to 64 characters of [a-z0-9_-]");
    return name;
}

// The primitive vectors as columns (the third e_z in 2D), refused when (nearly) degenerate.
Eigen::Matrix3d read_basis(const JsonNode& node, int dim)
{
    node.expect_array(static_cast<std::size_t>(dim), static_cast<std::size_t>(dim));
    Eigen::Matrix3d basis = Eigen::Matrix3d::Identity();
    for (int i = 0; i < dim; ++i) basis.col(i) = read_vector(node[static_cast<std::size_t>(i)], dim, max_coordinate);
    double lengths = 1;
    for (int i = 0; i < dim; ++i) lengths *= basis.col(i).norm();
    // Nearly degenerate bases are refused too: their reduced vectors would be known only
    // to about 1e-16 / ratio, not to the shell tolerance.
    if (lengths == 0 || std::abs(basis.determinant()) < 1e-6 * lengths)
        node.error(dim == 2 ? "degenerate basis: the vectors are collinear or zero (cell area below 1e-6 of the "
                              "product of their lengths), expected two independent vectors"
                            : "degenerate basis: the vectors are coplanar or zero (cell volume below 1e-6 of the "
                              "product of their lengths), expected three independent vectors");
    return basis;
}

// The motif's fractional coordinates wrapped into [0, 1); two sites at one position are refused.
std::vector<Eigen::Vector3d> read_motif(const JsonNode& node, const Eigen::Matrix3d& basis, int dim)
{
    node.expect_array(1, 1000);
    std::vector<Eigen::Vector3d> motif;
    for (std::size_t i = 0; i < node.size(); ++i) {
        Eigen::Vector3d f = read_vector(node[i], dim, 1e3);
        for (int c = 0; c < dim; ++c) {
            f[c] -= std::floor(f[c]);
            if (f[c] > 1 - 1e-12) f[c] = 0; // wrap 0.9999999999999 to 0
        }
        for (std::size_t j = 0; j < motif.size(); ++j) {
            Eigen::Vector3d delta = f - motif[j];
            for (int c = 0; c < dim; ++c) delta[c] -= std::round(delta[c]);
            if ((basis * delta).norm() < 1e-6 * std::pow(std::abs(basis.determinant()), 1.0 / dim))
                node[i].error("duplicate motif site: the same position as /motif/" + std::to_string(j));
        }
        motif.push_back(f);
    }
    return motif;
}

// Rescales the basis so that the nearest-neighbour distance is 1, and keeps the file's.
void scale_to_unit_distance(Lattice& lattice, const JsonNode& basis_node)
{
    const int dim = lattice.dimension;
    double d = nearest_neighbour_distance(lattice.basis, dim, lattice.motif);
    if (!(d > 1e-6 * lattice.basis.colwise().norm().maxCoeff()))
        basis_node.error("absurd geometry: the nearest-neighbour distance is below 1e-6 of the cell size");
    lattice.basis /= d;
    lattice.file_nearest_distance = d;
    // Once more in the scaled units, with the very arithmetic the shells use, so that the
    // first shell is at 1 to rounding even for a badly conditioned basis.
    lattice.basis /= nearest_neighbour_distance(lattice.basis, dim, lattice.motif);
    if (dim == 2) lattice.basis.col(2) = Eigen::Vector3d::UnitZ();
}

// The file's gravity, normalised, or straight down (-y in 2D, -z in 3D).
Eigen::Vector3d read_gravity(const JsonNode& root, int dim)
{
    auto g = root.find("gravity");
    if (!g) return dim == 2 ? Eigen::Vector3d(0, -1, 0) : Eigen::Vector3d(0, 0, -1);
    Eigen::Vector3d v = read_vector(*g, dim, max_coordinate);
    if (v.cwiseAbs().maxCoeff() == 0) g->error("gravity has zero length, expected a non-zero direction vector");
    return v.stableNormalized();
}

// The computed volume coefficients (voronoi, ball, cube), then the file's own.
std::vector<VolumeCoefficient> read_volume_coefficients(const JsonNode& root, const Lattice& lattice)
{
    std::vector<VolumeCoefficient> coefficients = {
        {"voronoi", lattice.volume_per_site(), "computed"},
        {"ball", lattice.dimension == 2 ? pi / 4 : pi / 6, "computed"},
        {"cube", 1.0, "computed"},
    };
    const std::size_t computed = coefficients.size();
    auto extra = root.find("volume_coefficients");
    if (!extra) return coefficients;
    extra->expect_object();
    for (const auto& [key, unused] : extra->value().items()) {
        auto value_node = extra->at(key);
        if (!is_identifier(key, {}, std::string::npos)) value_node.error("expected a name of [a-z0-9_]");
        // Only the computed names can clash (the parser refuses a key given twice): linear in the keys.
        for (std::size_t i = 0; i < computed; ++i)
            if (coefficients[i].name == key)
                value_node.error("\"" + key + "\" is computed by sphkern and cannot be redefined");
        double v = value_node.number();
        if (v <= 0 || v > 1e6) value_node.error("expected a positive volume coefficient up to 1e6");
        coefficients.push_back({key, v, lattice.file});
    }
    return coefficients;
}

} // namespace

double Lattice::volume_per_site() const { return std::abs(basis.determinant()) / sites(); }

double Lattice::volume_coefficient(const std::string& spec) const
{
    for (const auto& c : volume_coefficients)
        if (c.name == spec) return c.value;
    char* end = nullptr;
    double value = std::strtod(spec.c_str(), &end);
    if (!spec.empty() && end && *end == '\0') return checked_volume_coefficient(value, spec);
    std::vector<std::string> names;
    std::string list;
    for (const auto& c : volume_coefficients) {
        names.push_back(c.name);
        list += (list.empty() ? "" : ", ") + c.name;
    }
    std::string message = "lattice " + name + " has no volume coefficient \"" + spec + "\"" + did_you_mean(spec, names);
    fail_unknown(message + "; expected one of " + list + " or a positive number");
}

Lattice read_lattice(const fs::path& file) { return parse_lattice(read_json_file(file), file.string()); }

Lattice parse_lattice(const nlohmann::json& document, const std::string& file)
{
    JsonNode root(document, file);
    root.expect_object();
    root.expect_keys({"$schema", "name", "title", "dimension", "basis", "motif", "volume_coefficients", "gravity"});

    Lattice lattice;
    lattice.file = file;
    lattice.name = read_lattice_name(root);
    lattice.title = root.find("title") ? printable_text(root.at("title").string()) : lattice.name;
    lattice.dimension = static_cast<int>(root.at("dimension").integer_in(2, 3));
    const auto basis_node = root.at("basis");
    lattice.basis = read_basis(basis_node, lattice.dimension);
    lattice.motif = read_motif(root.at("motif"), lattice.basis, lattice.dimension);
    scale_to_unit_distance(lattice, basis_node);
    lattice.gravity = read_gravity(root, lattice.dimension);
    lattice.volume_coefficients = read_volume_coefficients(root, lattice);
    return lattice;
}

std::vector<std::string> shipped_lattice_names()
{
    std::vector<std::string> names;
    std::error_code ec;
    const fs::path folder = data_folder("lattices");
    fs::directory_iterator entries(folder, ec);
    if (ec && is_resource_error(ec.value())) fail_resource(ec.value(), "listing " + folder.string());
    for (const auto& entry : entries) {
        auto p = entry.path();
        if (p.extension() == ".json" && p.filename().string().find(".schema.") == std::string::npos)
            names.push_back(p.stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

Lattice load_lattice(const std::string& spec)
{
    if (looks_like_path(spec, ".json")) return read_lattice(spec);
    auto names = shipped_lattice_names();
    if (std::find(names.begin(), names.end(), spec) != names.end())
        return read_lattice(data_folder("lattices") / (spec + ".json"));
    std::string message = "unknown lattice \"" + spec + "\"" + did_you_mean(spec, names);
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    fail_unknown(message + "; shipped lattices: " + list + ", or give a path to a lattice file");
}

Eigen::Vector3d direction_of(const std::vector<double>& components, int dimension, const ValueSource& source)
{
    if (static_cast<int>(components.size()) != dimension)
        fail_input(fmt::format("{}: {} components, expected {} (one per dimension)", source.name, components.size(),
                               dimension));
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (int i = 0; i < dimension; ++i) v[i] = components[static_cast<std::size_t>(i)];
    if (!v.allFinite() || v.cwiseAbs().maxCoeff() == 0)
        source.fail("expected a direction: finite components, not all zero");
    return v.stableNormalized();
}

double checked_volume_coefficient(double a_p, const std::string& text)
{
    if (!std::isfinite(a_p) || a_p <= 0 || a_p > 1e6)
        fail_input("volume coefficient a_p = " + text + " is not allowed, expected a positive number up to 1e6");
    return a_p;
}

} // namespace sphkern
