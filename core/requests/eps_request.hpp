// One eps request, whichever front end built it (the command line's `eps`, Python's
// sphkern.eps): the bulk errors of a kernel on a lattice, at one k for every site (with
// the worst), or at many k for one site.
#pragma once

#include "analysis/resolution_axis.hpp"
#include "analysis/site_errors.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "requests/code_setting.hpp"
#include "requests/evaluation_inputs.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sphkern {

struct EpsRequest {
    std::vector<double> k;           // on `axis`: the command line gives one, Python an array (flattened)
    Axis axis = Axis::k;             // k or eta; nh names a window, not a value
    std::optional<CodeSetting> code; // instead of k (the command line's one value)
    EvaluationInputs evaluation;
};

// How the front end names each value in its errors ("--k" or "k").
struct EpsSources {
    ValueSource k, axis;
    EvaluationSources evaluation;
    ValueSource code, code_value; // "--code" and the code's parameter ("--eta")
};

// Every value that does not need the kernel or lattice; an Error naming its source.
void check_eps_request(const EpsRequest& request, const EpsSources& sources);

// Both errors at one k at every site; the top-level values are the chosen site's.
struct EpsAtK {
    std::string kernel, lattice; // the kernel's label and the lattice's name
    int dimension = 0;
    Axis axis = Axis::k;
    double k = 0, a_p = 0, eta = 0, support_radius = 0; // support_radius: H/d = R k
    int site = 0;                                       // the chosen site, checked against the lattice by run_eps_at_k
    std::optional<CodeK> code;                          // the code's setting given, whose k this is
    std::vector<SiteReport> sites;                      // every site of the lattice, in order: sites[s].site == s
    std::size_t worst = 0;                              // index into sites
    // Bounds-checked: an EpsAtK built by hand with a site it lacks throws, never reads past the end.
    const ErrorValues& chosen() const { return sites.at(static_cast<std::size_t>(site)).values; }
};
// The request's one k (converted from eta when given on that axis).
EpsAtK run_eps_at_k(const EpsRequest& request, const EpsSources& sources, const Kernel& kernel, const Lattice& lattice);

// Both errors at the chosen site for every k of the request, in its order.
std::vector<ErrorValues> run_eps_series(const EpsRequest& request, const EpsSources& sources, const Kernel& kernel,
                                        const Lattice& lattice);

// The document `sphkern eps --json` prints (without provenance and inputs).
nlohmann::json eps_document(const EpsAtK& result);
// The text `sphkern eps` prints, on the results file.
void print_eps(const EpsAtK& result);

} // namespace sphkern
