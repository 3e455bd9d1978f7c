#include "study/results_writer.hpp"

#include "analysis/code_conventions.hpp"
#include "analysis/results_json.hpp"
#include "stability/stability_json.hpp"
#include "study/particles_outputs.hpp"
#include "support/io/chunked_writer.hpp"
#include "support/io/provenance.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace sphkern {

namespace {

nlohmann::json per_site_json(const StudyCase& c, double epsilon)
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : c.per_site) list.push_back(site_roots_json(p, epsilon));
    return list;
}

nlohmann::json stability_json(const StabilityCase& c)
{
    nlohmann::json entry = {{"lattice", c.lattice}, {"kernel", c.kernel_label}, {"gamma", c.gamma},
                            {"h_model", c.h_model}};
    if (c.refused) {
        entry["refused"] = *c.refused;
        return entry;
    }
    nlohmann::json ks = nlohmann::json::array(), minima = nlohmann::json::array(), stable = nlohmann::json::array(),
                   verdicts = nlohmann::json::array(), growth = nlohmann::json::array(), kinds = nlohmann::json::array(),
                   overlap = nlohmann::json::array();
    for (const auto& s : c.over_k.samples) {
        ks.push_back(s.k);
        minima.push_back(s.branch_minima);
        stable.push_back(s.stable);
        verdicts.push_back(verdict_name(s.verdict));
        const bool grows = std::isfinite(s.growth_time);
        growth.push_back(grows ? nlohmann::json(s.growth_time) : nlohmann::json());
        kinds.push_back(grows ? nlohmann::json(mode_kind_name(s.mode.kind)) : nlohmann::json());
    }
    for (const auto& o : c.overlap) {
        auto recommended = recommended_json(o.recommended);
        for (std::size_t i = 0; i < o.in_conventions.size(); ++i) // a convention undefined for the kernel is left out
            if (std::isfinite(o.in_conventions[i])) recommended["conventions"][code_conventions()[i].name] = o.in_conventions[i];
        overlap.push_back({{"volume_coefficient", o.ap_name}, {"accurate", intervals_json(o.accurate)},
                           {"accurate_and_stable", intervals_json(o.both)}, {"recommended", recommended}});
    }
    entry.update({{"bravais", c.over_k.bravais}, {"k", ks}, {"branch_minima", minima}, {"stable", stable},
                  {"horizon", c.over_k.horizon}, {"verdict", verdicts}, {"growth_time", growth}, {"mode", kinds},
                  {"stable_intervals", intervals_json(c.over_k.stable)},
                  {"stable_at_horizon", intervals_json(c.over_k.usable)}, {"overlap", overlap},
                  {"dispersion", {{"k", c.path_k}, {"path", dispersion_path_json(c.path)}}}});
    return entry;
}

nlohmann::json explanations_json(const StudyCase& c)
{
    nlohmann::json explanations = nlohmann::json::array();
    for (const auto& e : c.explanations) {
        nlohmann::json diffs = nlohmann::json::array();
        for (const auto& d : e.differences)
            diffs.push_back({{"radius", d.radius}, {"count", d.count}, {"reason", d.reason}, {"q", d.q},
                             {"contribution", d.contribution}});
        explanations.push_back({{"function", function_name(e.root.function)}, {"k", e.root.k},
                                {"default_value", e.default_value},
                                {"default_root_k", e.default_root_k ? nlohmann::json(*e.default_root_k) : nullptr},
                                {"differences", diffs}});
    }
    return explanations;
}

// A case without its curve, as text without the closing brace: the curve follows.
std::string case_head(const StudyCase& c, double epsilon)
{
    auto scan = root_scan_json(c.scan);
    std::string head = nlohmann::json{{"lattice", c.lattice}, {"mode", c.mode}, {"kernel", c.kernel_label},
                                      {"volume_coefficient", c.ap_name}, {"a_p", c.a_p}, {"roots", scan["roots"]},
                                      {"jumps", scan["jumps"]},
                                      {"sites", c.sites},
                                      {"acceptance", acceptance_json(c.acceptance, epsilon)},
                                      {"acceptance_every_direction", acceptance_json(c.acceptance_every, epsilon)},
                                      {"per_site", per_site_json(c, epsilon)},
                                      {"explanations", explanations_json(c)}}
                           .dump();
    head.pop_back();
    return head;
}

// The curve, number by number: "k", "eps_rho", "eps_gradp" and "neighbours" arrays.
void write_curve(ChunkedWriter& w, const StudyCase& c)
{
    auto number = [&](double v) {
        if (std::isfinite(v)) w.print("{}", v);
        else w.text("null");
    };
    const char* fields[] = {"k", "eps_rho", "eps_gradp", "neighbours"};
    w.text(", \"curve\": {");
    for (int f = 0; f < 4; ++f) {
        w.print("{}\"{}\": [", f ? ", " : "", fields[f]);
        for (std::size_t j = 0; j < c.curve.size(); ++j) {
            if (j) w.text(",");
            const auto& [k, v] = c.curve[j];
            if (f == 3) w.print("{}", v.neighbours);
            else number(f == 0 ? k : f == 1 ? v.eps_rho : v.eps_gradp);
        }
        w.text("]");
    }
    w.text("}}");
}

nlohmann::json comparison_json(const StudyResults& results)
{
    nlohmann::json comparison = nlohmann::json::array();
    for (const auto& r : results.comparison)
        comparison.push_back({{"reference", r.reference},
                              {"function", r.function ? nlohmann::json(function_name(*r.function)) : nlohmann::json("none")},
                              {"computed", r.computed ? root_json(*r.computed) : nlohmann::json(nullptr)},
                              {"compared", r.compared},
                              {"differs_in", r.differing},
                              {"status", status_name(r.status)},
                              {"note", r.note}});
    return comparison;
}

nlohmann::json surface_results_json(const StudyResults& results)
{
    nlohmann::json surface = nlohmann::json::array();
    for (const auto& c : results.surface) {
        auto entry = surface_json(c.profile);
        entry.update({{"lattice", c.lattice}, {"kernel", c.kernel_label}, {"form", c.form},
                      {"volume_coefficient", c.ap_name}, {"a_p", c.a_p}, {"k", c.k}});
        surface.push_back(entry);
    }
    return surface;
}

nlohmann::json sweeps_json(const StudyResults& results, double epsilon)
{
    nlohmann::json sweeps = nlohmann::json::array();
    for (const auto& c : results.sweeps) {
        nlohmann::json solutions = nlohmann::json::array();
        for (std::size_t i = 0; i < c.design.solutions.size(); ++i) {
            const auto& s = c.design.solutions[i];
            solutions.push_back({{"k", s.k}, {"parameter", s.parameter}, {"eps_rho", s.values.eps_rho},
                                 {"eps_gradp", s.values.eps_gradp}, {"jacobian_condition", s.jacobian_condition},
                                 {"non_negative", s.non_negative},
                                 {"acceptance", acceptance_json(c.designed_acceptance[i], epsilon)}});
        }
        sweeps.push_back({{"lattice", c.lattice}, {"kernel", c.kernel}, {"parameter", c.parameter},
                          {"volume_coefficient", c.ap_name}, {"a_p", c.a_p}, {"k", c.ks}, {"values", c.values},
                          {"eps_rho", c.rho}, {"eps_gradp", c.gradp}, {"solutions", solutions}, {"note", c.design.note}});
    }
    return sweeps;
}

} // namespace

// Streamed: every part but the curves is a small JSON value; the curves, most of the
// document, are written number by number without building a JSON tree for them.
void write_study_results_json(std::ostream& out, const Study& study, const StudyResults& results)
{
    ChunkedWriter w(out);
    w.print("{{\n \"sphkern_version\": {},\n \"provenance\": {},\n \"study_file\": {},\n \"study\": {},\n "
            "\"inputs\": {},\n \"cases\": [",
            nlohmann::json(SPHKERN_VERSION).dump(), provenance().dump(), nlohmann::json(study.file).dump(),
            study.document.dump(), results.inputs.dump());
    for (std::size_t i = 0; i < results.cases.size(); ++i) {
        w.text(i ? ",\n  " : "\n  ");
        w.text(case_head(results.cases[i], study.epsilon));
        write_curve(w, results.cases[i]);
    }
    nlohmann::json stability = nlohmann::json::array();
    for (const auto& c : results.stability) stability.push_back(stability_json(c));
    w.print("\n ],\n \"comparison\": {},\n \"surface\": {},\n \"sweeps\": {},\n \"stability\": {},\n \"particles\": {}\n}}\n",
            comparison_json(results).dump(1), surface_results_json(results).dump(1), sweeps_json(results, study.epsilon).dump(1),
            stability.dump(1), particles_results_json(results).dump(1));
}

} // namespace sphkern
