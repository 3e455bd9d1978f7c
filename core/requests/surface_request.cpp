#include "requests/surface_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "analysis/results_json.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sphkern {

void check_surface_request(const SurfaceRequest& r, const SurfaceSources& sources)
{
    if (r.code) check_code_setting(*r.code, {sources.code, sources.code_value});
    else check_k(r.k, sources.k);
    check_setting(settings_of("surface")["layers"], r.layers, sources.layers);
    check_evaluation(r.evaluation, sources.evaluation);
}

SurfaceResult run_surface(const SurfaceRequest& r, const SurfaceSources& sources, const Kernel& kernel,
                          const Lattice& lattice)
{
    auto evaluation = resolve_evaluation(r.evaluation, sources.evaluation, lattice);
    SurfaceResult result{r.k, evaluation.a_p, {}, {}};
    if (r.code) {
        result.code = k_of_code_setting(*r.code, {sources.code, sources.code_value}, kernel, lattice, evaluation);
        result.k = result.code->k;
        if (result.code->a_p) evaluation.a_p = result.a_p = *result.code->a_p; // the code's volume, not the lattice's
    }
    result.profile = surface_profile(kernel, lattice, evaluation.site, evaluation.a_p, evaluation.gravity, result.k,
                                     r.layers, r.form, r.termination);
    return result;
}

nlohmann::json surface_request_document(const SurfaceRequest& r, const SurfaceResult& result, const Kernel& kernel,
                                        const Lattice& lattice)
{
    auto document = surface_document(kernel, lattice, result.k, result.a_p, r.form, result.profile);
    if (result.code) document["code"] = code_k_json(*result.code);
    return document;
}

namespace {

// The first line: the kernel, lattice and form, and the planes' terminations when there are several sites.
void print_surface_heading(const SurfaceRequest& r, const SurfaceResult& result, const Kernel& kernel,
                           const Lattice& lattice)
{
    const auto& profile = result.profile;
    const std::string k = result.code ? fmt::format("{:.10g} ({} {} = {:.10g})", result.k, result.code->setting.code,
                                                    result.code->parameter, result.code->setting.value)
                                      : fmt::format("{}", result.k);
    if (lattice.sites() == 1)
        return fmt::print(results_file(), "{} on {}, k = {}, a_p = {:.10g}, form {}, layer spacing {:.6f} d\n",
                          kernel.label(), lattice.name, k, result.a_p, gradient_form_name(r.form), profile.spacing);
    std::string names;
    for (std::size_t t = 0; t < profile.planes.types.size(); ++t)
        names += fmt::format("{}{}: {}", t ? ", " : "", t, profile.planes.name(static_cast<int>(t)));
    fmt::print(results_file(),
               "{} on {}, k = {}, a_p = {:.10g}, form {}; the occupied planes repeat every {:.6f} d; "
               "terminations {}; on top: {}\n",
               kernel.label(), lattice.name, k, result.a_p, gradient_form_name(r.form), profile.spacing, names,
               profile.termination);
}

} // namespace

void print_surface(const SurfaceRequest& r, const SurfaceResult& result, const Kernel& kernel, const Lattice& lattice)
{
    const auto& profile = result.profile;
    const bool one_site = lattice.sites() == 1;
    print_surface_heading(r, result, kernel, lattice);
    fmt::print(results_file(), "{:>5} {:>10} {}{:>6} {:>14} {:>14}\n", "layer", "depth/d", one_site ? "" : " site", "N",
               "eps_rho", "eps_gradP");
    for (const auto& l : profile.layers)
        for (const auto& v : l.sites)
            fmt::print(results_file(), "{:>5} {:>10.5f} {}{:>6} {:>14.8f} {:>14.8f}\n", l.n, l.depth,
                       one_site ? "" : fmt::format("{:>5}", v.site), v.neighbours, v.eps_rho, v.eps_gradp);
    for (const auto& v : profile.bulk.sites)
        fmt::print(results_file(), "{:>5} {:>10} {}{:>6} {:>14.8f} {:>14.8f}\n", "bulk", "",
                   one_site ? "" : fmt::format("{:>5}", v.site), v.neighbours, v.eps_rho, v.eps_gradp);
    for (std::size_t s = 0; s < profile.first_moments.size(); ++s)
        if (profile.first_moments[s].norm() > 1e-9)
            fmt::print(results_file(),
                       "site {} is not a centre of inversion (first moment {:.3g}): with the sum form its gradient "
                       "error grows with depth by 2 P_i m1; the bulk row leaves that term out\n",
                       s, profile.first_moments[s].norm());
}

} // namespace sphkern
