#include "lattices/lattice_json.hpp"

#include "lattices/shells.hpp"

#include <nlohmann/json.hpp>

namespace sphkern {

nlohmann::json lattice_json(const Lattice& l)
{
    nlohmann::json coefficients = nlohmann::json::object();
    for (const auto& c : l.volume_coefficients) coefficients[c.name] = c.value;
    std::vector<double> gravity(l.gravity.data(), l.gravity.data() + l.dimension);
    return {{"name", l.name},
            {"title", l.title},
            {"dimension", l.dimension},
            {"sites", l.sites()},
            {"volume_coefficients", coefficients},
            {"gravity", gravity},
            {"file", l.file}};
}

nlohmann::json lattice_description_json(const Lattice& lattice, double radius)
{
    auto document = lattice_json(lattice);
    document["nearest_neighbour_distance"] = 1.0;
    document["nearest_neighbour_distance_in_file_units"] = lattice.file_nearest_distance;
    nlohmann::json sites = nlohmann::json::array();
    for (int s = 0; s < lattice.sites(); ++s) {
        const Eigen::Vector3d& m = lattice.motif[static_cast<std::size_t>(s)];
        const Eigen::Vector3d x = lattice.basis * m;
        sites.push_back({{"site", s},
                         {"fractional", std::vector<double>(m.data(), m.data() + lattice.dimension)},
                         {"position", std::vector<double>(x.data(), x.data() + lattice.dimension)},
                         {"shells", shell_rows_json(shell_rows(lattice, s, radius, lattice.gravity))}});
    }
    document["shells_radius"] = radius;
    document["site_details"] = sites;
    return document;
}

nlohmann::json shell_rows_json(const std::vector<ShellRow>& rows)
{
    nlohmann::json list = nlohmann::json::array();
    for (const ShellRow& s : rows)
        list.push_back({{"radius", s.radius},
                        {"radius_squared", s.radius * s.radius},
                        {"count", s.count},
                        {"cumulative", s.cumulative},
                        {"gravity_moment", s.moment_along}});
    return list;
}

} // namespace sphkern
