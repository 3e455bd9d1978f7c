// One surface request, whichever front end built it (the command line's `surface`,
// Python's sphkern.surface): the errors layer by layer below a free surface.
#pragma once

#include "analysis/gradient_form.hpp"
#include "analysis/surface_profile.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "requests/code_setting.hpp"
#include "requests/evaluation_inputs.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>

namespace sphkern {

struct SurfaceRequest {
    double k = 0;
    std::optional<CodeSetting> code; // instead of k: a code's own setting, its k from the bulk at the top site
    int layers = 4;                  // at least this many layers below the surface
    GradientForm form = GradientForm::sum;
    std::optional<int> termination; // which plane type is on top; none: the site's
    EvaluationInputs evaluation;    // a_p, gravity and the site on top (every shell)
};

// How the front end names each value in its errors.
struct SurfaceSources {
    ValueSource k;
    EvaluationSources evaluation;
    ValueSource layers;
    ValueSource code, code_value; // "--code" and the code's parameter ("--eta")
};

// Every value that does not need the kernel or lattice; an Error naming its source.
void check_surface_request(const SurfaceRequest& request, const SurfaceSources& sources);

struct SurfaceResult {
    double k = 0, a_p = 0;
    std::optional<CodeK> code; // the code's setting given, whose k this is
    SurfaceProfile profile;
};

SurfaceResult run_surface(const SurfaceRequest& request, const SurfaceSources& sources, const Kernel& kernel,
                          const Lattice& lattice);

// The document `sphkern surface --json` prints (without provenance and inputs).
nlohmann::json surface_request_document(const SurfaceRequest& request, const SurfaceResult& result,
                                        const Kernel& kernel, const Lattice& lattice);
// The text `sphkern surface` prints, on the results file.
void print_surface(const SurfaceRequest& request, const SurfaceResult& result, const Kernel& kernel,
                   const Lattice& lattice);

} // namespace sphkern
