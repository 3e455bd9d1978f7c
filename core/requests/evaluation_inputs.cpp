#include "requests/evaluation_inputs.hpp"

#include "lattices/numeric_inputs.hpp"

#include <fmt/format.h>

namespace sphkern {

void check_evaluation(const EvaluationInputs& inputs, const EvaluationSources& sources)
{
    for (double r : inputs.shell_radii)
        if (r <= 0) sources.shells.fail(fmt::format("\"{}\" is not a positive number", r));
}

double volume_coefficient_of(const Lattice& lattice, const VolumeCoefficientInput& a_p)
{
    if (const auto* name = std::get_if<std::string>(&a_p)) return lattice.volume_coefficient(*name);
    const double value = std::get<double>(a_p);
    return checked_volume_coefficient(value, fmt::format("{}", value));
}

Evaluation resolve_evaluation(const EvaluationInputs& inputs, const EvaluationSources& sources, const Lattice& lattice)
{
    Evaluation e;
    e.a_p = volume_coefficient_of(lattice, inputs.a_p);
    check_site(inputs.site, lattice.sites(), lattice.name, sources.site);
    e.site = inputs.site;
    e.gravity = inputs.gravity ? direction_of(*inputs.gravity, lattice.dimension, sources.gravity) : lattice.gravity;
    if (!inputs.shell_radii.empty()) e.mode.shell_radii = inputs.shell_radii;
    e.mode.continue_past_support = inputs.continue_past_support;
    return e;
}

} // namespace sphkern
