#include "lattices/shells.hpp"

#include "lattices/lattice_points.hpp"
#include "support/error.hpp"
#include "support/process/work_budget.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sphkern {

std::vector<Shell> lattice_shells(const Lattice& lattice, int site, double r_max)
{
    std::ostringstream s;
    if (!std::isfinite(r_max) || r_max <= 0) {
        s << "radius " << r_max << " is not allowed, expected a positive number (in units of d)";
        fail_input(s.str());
    }
    if (site < 0 || site >= lattice.sites())
        fail_input(site_range(lattice.name, lattice.sites()) + ", not " + std::to_string(site));
    double bound = lattice_point_bound(r_max, lattice.dimension);
    check_work_budget(fmt::format("radius {}", r_max), "lattice points inside it (at most)", bound,
                      static_cast<double>(max_lattice_points));
    std::vector<Eigen::Vector3d> points;
    points.reserve(static_cast<std::size_t>(bound));
    for_each_lattice_point(lattice.basis, lattice.dimension, lattice.motif, site, r_max,
                           [&](const Eigen::Vector3d& x) { points.push_back(x); });
    std::vector<std::pair<double, std::size_t>> order(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) order[i] = {points[i].norm(), i};
    std::sort(order.begin(), order.end());

    std::vector<Shell> shells;
    for (const auto& [r, i] : order) {
        if (shells.empty() || r - shells.back().radius > shell_tolerance) {
            Shell shell;
            shell.radius = r;
            shell.moment.setZero();
            shells.push_back(shell);
        }
        Eigen::Vector3d u = points[i] / r;
        shells.back().count += 1;
        shells.back().moment += u * u.transpose();
        shells.back().first += u;
    }
    return shells;
}

std::vector<ShellRow> shell_rows(const Lattice& lattice, int site, double r_max, const Eigen::Vector3d& e)
{
    std::vector<ShellRow> rows;
    int total = 0;
    for (const Shell& s : lattice_shells(lattice, site, r_max)) {
        total += s.count;
        rows.push_back({s.radius, s.count, total, s.directional_moment(e)});
    }
    return rows;
}

} // namespace sphkern
