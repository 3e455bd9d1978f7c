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

ShellsResult run_shells(const ShellsRequest& r, const ShellsSources& sources, const Lattice& lattice)
{
    check_positive(r.radius, sources.radius);
    check_site(r.site, lattice.sites(), lattice.name, sources.site);
    const Eigen::Vector3d e =
        r.gravity ? direction_of(*r.gravity, lattice.dimension, sources.gravity) : lattice.gravity;
    return {lattice.name, r.site, r.radius, shell_rows(lattice, r.site, r.radius, e)};
}

nlohmann::json shells_json(const ShellsResult& result)
{
    return {{"lattice", result.lattice},
            {"site", result.site},
            {"radius", result.radius},
            {"shells", shell_rows_json(result.shells)}};
}

void print_shells(const ShellsResult& result)
{
    fmt::print(results_file(), "{:>12} {:>10} {:>6} {:>10} {:>14}\n", "radius/d", "radius^2", "count", "total",
               "sum (e.r^)^2");
    for (const ShellRow& s : result.shells)
        fmt::print(results_file(), "{:>12.8f} {:>10.6f} {:>6} {:>10} {:>14.8f}\n", s.radius, s.radius * s.radius,
                   s.count, s.cumulative, s.moment_along);
}

} // namespace sphkern
