#include "study/study_inputs.hpp"

#include "analysis/resolution_axis.hpp"
#include "analysis/site_errors.hpp"
#include "study/sections/section_table.hpp"
#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace sphkern {

namespace {

std::string support_key(double R)
{
    std::ostringstream s;
    s << R;
    return s.str();
}

std::string lattice_path(std::size_t i) { return "/lattices/" + std::to_string(i); }

// One name, one table: two lattices or kernels that print alike would be merged.
void check_names_differ(const Study& study, const StudyInputs& inputs)
{
    const auto& lattices = inputs.lattices;
    for (std::size_t i = 0; i < lattices.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (lattices[i].name == lattices[j].name)
                study_source(study, lattice_path(i))
                    .fail("lattice name \"" + lattices[i].name + "\" is already used by " + lattice_path(j) +
                          "; give each lattice its own name");
    const auto& kernels = inputs.kernels;
    for (std::size_t i = 0; i < kernels.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (kernels[i].label() == kernels[j].label())
                study_source(study, study.kernels[i].json_path)
                    .fail("kernel \"" + kernels[i].label() + "\" is listed twice (also at " +
                          study.kernels[j].json_path + ")");
}

void load_kernels_and_lattices(const Study& study, KernelRegistry& registry, StudyInputs& inputs)
{
    for (const auto& k : study.kernels)
        inputs.kernels.push_back(
            at_source(study_source(study, k.json_path), [&] { return Kernel(registry.find(k.spec), k.parameters); }));
    for (std::size_t i = 0; i < study.lattices.size(); ++i)
        inputs.lattices.push_back(
            at_source(study_source(study, lattice_path(i)), [&] { return load_lattice(study.lattices[i]); }));
    check_names_differ(study, inputs);
    for (std::size_t i = 0; i < inputs.kernels.size(); ++i)
        for (const auto& l : inputs.lattices)
            at_source(study_source(study, study.kernels[i].json_path),
                      [&] { inputs.kernels[i].require_dimension(l.dimension, l.name); });
}

// Each lattice's a_p and the sites studied.
void resolve_lattice_values(const Study& study, StudyInputs& inputs)
{
    for (const auto& lattice : inputs.lattices) {
        auto& aps = inputs.a_p.emplace_back();
        for (std::size_t i = 0; i < study.volume_coefficients.size(); ++i)
            aps.push_back(at_source(study_source(study, "/volume_coefficients/" + std::to_string(i)),
                                    [&] { return study.volume_coefficients[i].on(lattice); }));
    }
    for (const auto& lattice : inputs.lattices) {
        const std::vector<int> sites = study.sites ? *study.sites : every_site(lattice);
        at_source(study_source(study, "/sites"), [&] { check_sites(lattice, sites, "sites"); });
        inputs.sites.push_back(sites);
    }
}

// The evaluation a mode asks of a kernel: its shell list for the kernel's support.
EvaluationMode evaluation_mode(const Study& study, const StudyMode& mode, const Kernel& kernel)
{
    EvaluationMode m;
    if (mode.shells_by_support.empty()) return m;
    const auto* radii = mode.shells_for(kernel.support());
    const std::string R = support_key(kernel.support());
    if (!radii)
        study_source(study, mode.json_path + "/shells")
            .fail("no shell list for kernel " + kernel.name() + " with support R = " + R + ", expected a key \"" + R +
                  "\"");
    m.shell_radii = *radii;
    m.continue_past_support = mode.continues(kernel.name());
    return m;
}

// A mode's "continue_past_support" names study kernels (by name): a misspelt name
// would otherwise silently evaluate that kernel truncated.
void check_continued_kernels(const Study& study, const StudyMode& mode, const std::vector<Kernel>& kernels)
{
    std::vector<std::string> names;
    for (const auto& kernel : kernels) names.push_back(kernel.name());
    for (std::size_t i = 0; i < mode.continue_kernels.size(); ++i) {
        const std::string& name = mode.continue_kernels[i];
        if (std::find(names.begin(), names.end(), name) == names.end())
            study_source(study, mode.json_path + "/continue_past_support/" + std::to_string(i))
                .fail("\"" + name + "\" is not one of the study's kernels" + did_you_mean(name, names));
    }
}

void resolve_reference(const Study& study, StudyInputs& inputs)
{
    if (!study.reference) return;
    StudyCaseNames names;
    for (const auto& l : inputs.lattices) names.lattices.push_back(l.name);
    for (const auto& m : study.modes) names.modes.push_back(m.name);
    for (const auto& ap : study.volume_coefficients) names.volume_coefficients.push_back(ap.name);
    for (const auto& k : inputs.kernels) names.kernels.push_back(k.name());
    inputs.reference = *study.reference;
    resolve_reference_table(*inputs.reference, names);
}

} // namespace

StudyInputs load_study_inputs(const Study& study, KernelRegistry& registry)
{
    StudyInputs inputs;
    load_kernels_and_lattices(study, registry, inputs);
    resolve_lattice_values(study, inputs);
    for (const auto& mode : study.modes) {
        check_continued_kernels(study, mode, inputs.kernels);
        auto& per_kernel = inputs.evaluation.emplace_back();
        for (const auto& kernel : inputs.kernels) per_kernel.push_back(evaluation_mode(study, mode, kernel));
    }
    for (std::size_t l = 0; l < inputs.lattices.size(); ++l) // the bulk cases' windows, at their first site
        for (std::size_t k = 0; k < inputs.kernels.size(); ++k)
            for (double a_p : inputs.a_p[l]) resolve_window(study, inputs, l, k, inputs.sites[l].front(), a_p);
    for (const auto& section : study.sections)
        inputs.sections.push_back(section ? section->resolve(study, registry, inputs) : SectionRun());
    inputs.parts = {"accuracy"};
    for (std::size_t i = 0; i < inputs.sections.size(); ++i)
        if (inputs.sections[i]) inputs.parts.emplace_back(section_table()[i].key);
    resolve_reference(study, inputs);
    return inputs;
}

std::string part_scope(const StudyInputs& inputs, const std::string& part)
{
    const auto& parts = inputs.parts;
    const auto at = std::find(parts.begin(), parts.end(), part);
    if (parts.size() < 2 || at == parts.end()) return "";
    std::string scope = fmt::format(" in this part ({} of {})", at - parts.begin() + 1, parts.size());
    for (auto next = at + 1; next != parts.end(); ++next)
        scope += (next == at + 1 ? ", then " : next + 1 == parts.end() ? " and " : ", ") + *next;
    return scope;
}

std::pair<double, double> study_window(const Study& study, const Kernel& kernel, const Lattice& lattice, int site,
                                       double a_p)
{
    return at_source(study_source(study, "/k"), [&] {
        return k_window(study.axis, study.k_min, study.k_max, kernel, lattice, site, a_p, "window");
    });
}

void resolve_window(const Study& study, StudyInputs& inputs, std::size_t lattice, std::size_t kernel, int site,
                    double a_p)
{
    const StudyInputs::WindowKey key{lattice, kernel, site, a_p};
    if (!inputs.windows.count(key))
        inputs.windows[key] = study_window(study, inputs.kernels[kernel], inputs.lattices[lattice], site, a_p);
}

std::pair<double, double> StudyInputs::window(std::size_t lattice, std::size_t kernel, int site, double a_p) const
{
    const auto it = windows.find({lattice, kernel, site, a_p});
    if (it == windows.end()) throw std::logic_error("a study window was not worked out before its section");
    return it->second;
}

std::optional<std::size_t> first_automatic_mode(const Study& study)
{
    for (std::size_t m = 0; m < study.modes.size(); ++m)
        if (study.modes[m].is_automatic()) return m;
    return std::nullopt;
}

} // namespace sphkern
