#include "requests/shells_request.hpp"

#include "lattices/lattice_json.hpp"
#include "lattices/numeric_inputs.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sphkern {

ShellsSources shells_sources(FrontEnd f)
{
    // A site the lattice lacks does not fit it (exit 3), as in every request.
    return {value_named(f, "radius"), {value_named(f, "site").name, ExitCode::input}, value_named(f, "gravity")};
}

nlohmann::json run_shells(const ShellsRequest& r, const ShellsSources& sources, const Lattice& lattice)
{
    check_positive(r.radius, sources.radius);
    check_site(r.site, lattice.sites(), lattice.name, sources.site);
    const Eigen::Vector3d e =
        r.gravity ? direction_of(*r.gravity, lattice.dimension, sources.gravity) : lattice.gravity;
    return shells_json(lattice, r.site, r.radius, e);
}

void print_shells(const nlohmann::json& document)
{
    fmt::print(results_file(), "{:>12} {:>10} {:>6} {:>10} {:>14}\n", "radius/d", "radius^2", "count", "total",
               "sum (e.r^)^2");
    for (const auto& s : document["shells"])
        fmt::print(results_file(), "{:>12.8f} {:>10.6f} {:>6} {:>10} {:>14.8f}\n", s["radius"].get<double>(),
                   s["radius_squared"].get<double>(), s["count"].get<int>(), s["cumulative"].get<int>(),
                   s["gravity_moment"].get<double>());
}

} // namespace sphkern
