#include "analysis/site_errors.hpp"

#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace sphkern {

std::vector<int> every_site(const Lattice& lattice)
{
    std::vector<int> sites;
    for (int s = 0; s < lattice.sites(); ++s) sites.push_back(s);
    return sites;
}

void check_sites(const Lattice& lattice, const std::vector<int>& sites, const std::string& what)
{
    if (sites.empty()) fail_input(what + ": an empty list of sites; " + site_range(lattice.name, lattice.sites()));
    for (int s : sites) check_site(s, lattice.sites(), lattice.name, ValueSource::argument(what));
}

std::vector<std::unique_ptr<HydrostaticErrors>> errors_per_site(const Kernel& kernel, const Lattice& lattice,
                                                                const std::vector<int>& sites, double a_p,
                                                                const Eigen::Vector3d& gravity, double k_max,
                                                                const EvaluationMode& mode)
{
    std::vector<std::unique_ptr<HydrostaticErrors>> errors;
    for (int s : sites)
        errors.push_back(std::make_unique<HydrostaticErrors>(kernel, lattice, s, a_p, gravity, k_max, mode));
    return errors;
}

SiteReport site_report(const HydrostaticErrors& errors, double k)
{
    return {errors.site(), errors.at(k), errors.tensor(k)};
}

std::size_t worst_site(const std::vector<SiteReport>& reports)
{
    std::size_t worst = 0;
    double largest = -1;
    for (std::size_t i = 0; i < reports.size(); ++i) {
        double e = std::max(std::abs(reports[i].values.eps_rho), std::abs(reports[i].values.eps_gradp));
        if (e > largest) {
            largest = e;
            worst = i;
        }
    }
    return worst;
}

nlohmann::json site_report_json(const SiteReport& r, int dimension)
{
    std::vector<double> first(r.gradient.first_moment.data(), r.gradient.first_moment.data() + dimension);
    return {{"site", r.site},
            {"eps_rho", r.values.eps_rho},
            {"eps_gradp", r.values.eps_gradp},
            {"eps_lateral", r.values.lateral},
            {"gradp_tensor_eigenvalues", r.gradient.eigenvalues},
            {"first_moment", first},
            {"neighbours", r.values.neighbours}};
}

} // namespace sphkern
