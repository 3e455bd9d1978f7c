#include "study/bulk_section.hpp"

#include "analysis/site_errors.hpp"
#include "support/process/interruption.hpp"
#include "support/process/progress.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

// For each root of a fixed-shell mode: the default evaluation there and each shell that differs.
std::vector<RootExplanation> explain(const HydrostaticErrors& mode, const HydrostaticErrors& automatic,
                                     const RootScan& scan, const RootScan& automatic_scan)
{
    std::vector<RootExplanation> explanations;
    const double R = mode.kernel().support();
    for (const auto& root : scan.roots) {
        const bool rho = root.function == ErrorFunction::rho;
        RootExplanation e;
        e.root = root;
        e.default_value = value_of(automatic.at(root.k), root.function);
        for (const auto& r : automatic_scan.roots)
            if (r.function == root.function &&
                (!e.default_root_k || std::abs(r.k - root.k) < std::abs(*e.default_root_k - root.k)))
                e.default_root_k = r.k;
        std::size_t active = mode.active_terms(root.k);
        for (std::size_t i = 0; i < active; ++i) {
            const Shell& s = mode.terms()[i];
            if (s.radius <= R * root.k) continue;
            auto c = mode.shell_contribution(s, root.k);
            e.differences.push_back(
                {s.radius, s.count, "evaluated past R", s.radius / root.k, rho ? c.first : c.second});
        }
        for (const auto& s : automatic.terms()) {
            if (s.radius > R * root.k) break;
            bool listed = std::any_of(mode.terms().begin(), mode.terms().end(),
                                      [&](const Shell& t) { return t.radius == s.radius; });
            if (listed) continue;
            auto c = automatic.shell_contribution(s, root.k);
            e.differences.push_back(
                {s.radius, s.count, "left out of the shell list", s.radius / root.k, rho ? c.first : c.second});
        }
        explanations.push_back(std::move(e));
    }
    return explanations;
}

} // namespace

namespace {

// One kernel x lattice x a_p x mode: the curve, roots, condition (22) and, for a fixed-shell
// mode, why its roots differ from the automatic evaluation.
StudyCase bulk_case(const Study& study, const StudyInputs& inputs, const CaseKey& key,
                    const HydrostaticErrors& automatic, const RootScan& automatic_scan)
{
    const Lattice& lattice = inputs.lattices[key.lattice];
    const Kernel& kernel = inputs.kernels[key.kernel];
    const StudyMode& mode = study.modes[key.mode];
    const std::vector<int>& sites = inputs.sites[key.lattice];
    const double a_p = inputs.a_p[key.lattice][key.volume_coefficient];
    const auto [k_min, k_max] = inputs.window(key.lattice, key.kernel, sites[0], a_p);
    StudyCase c;
    c.key = key;
    c.lattice = lattice.name;
    c.dimension = lattice.dimension;
    c.mode = mode.name;
    c.automatic = mode.is_automatic();
    c.kernel = kernel.name();
    c.kernel_label = kernel.label();
    c.support = kernel.support();
    c.ap_name = study.volume_coefficients[key.volume_coefficient].name;
    c.a_p = a_p;
    c.k_min = k_min;
    c.k_max = k_max;
    c.sites = sites;
    auto errors =
        errors_per_site(kernel, lattice, sites, a_p, lattice.gravity, k_max, inputs.evaluation[key.mode][key.kernel]);
    for (int i = 0; i < study.samples; ++i) {
        if (i % 64 == 0) throw_if_interrupted();
        double k = k_min + (k_max - k_min) * i / (study.samples - 1);
        c.curve.emplace_back(k, errors[0]->at(k));
    }
    c.scan = c.automatic ? automatic_scan : find_roots(*errors[0], k_min, k_max);
    const AcceptanceRule along{study.epsilon, Direction::gravity, study.lateral};
    const AcceptanceRule every{study.epsilon, Direction::every, study.lateral};
    std::vector<const HydrostaticErrors*> all;
    for (const auto& e : errors) all.push_back(e.get());
    c.acceptance = evaluate_acceptance(all, k_min, k_max, along);
    c.acceptance_every = evaluate_acceptance(all, k_min, k_max, every);
    if (errors.size() > 1)
        for (std::size_t i = 0; i < errors.size(); ++i)
            c.per_site.push_back({sites[i], i == 0 ? c.scan : find_roots(*errors[i], k_min, k_max),
                                  evaluate_acceptance({errors[i].get()}, k_min, k_max, along),
                                  evaluate_acceptance({errors[i].get()}, k_min, k_max, every)});
    if (!c.automatic) c.explanations = explain(*errors[0], automatic, c.scan, automatic_scan);
    return c;
}

} // namespace

void run_bulk_section(const Study& study, const StudyInputs& inputs, StudyResults& results)
{
    Progress progress("study " + study.name + ", accuracy",
                      inputs.lattices.size() * inputs.kernels.size() * study.volume_coefficients.size() *
                          study.modes.size(),
                      part_scope(inputs, "accuracy"));
    for (std::size_t l = 0; l < inputs.lattices.size(); ++l) {
        const Lattice& lattice = inputs.lattices[l];
        const int site = inputs.sites[l][0];
        for (std::size_t k = 0; k < inputs.kernels.size(); ++k)
            for (std::size_t a = 0; a < inputs.a_p[l].size(); ++a) {
                const double a_p = inputs.a_p[l][a];
                const auto [k_min, k_max] = inputs.window(l, k, site, a_p);
                HydrostaticErrors automatic(inputs.kernels[k], lattice, site, a_p, lattice.gravity, k_max);
                RootScan automatic_scan = find_roots(automatic, k_min, k_max);
                for (std::size_t m = 0; m < study.modes.size(); ++m) {
                    results.cases.push_back(bulk_case(study, inputs, {l, k, a, m}, automatic, automatic_scan));
                    progress.step(inputs.kernels[k].name() + " on " + lattice.name);
                    throw_if_interrupted();
                }
            }
    }
}

} // namespace sphkern
