#include "study/results_writer.hpp"

#include "analysis/results_json.hpp"
#include "study/sections/section_table.hpp"
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

nlohmann::json explanations_json(const StudyCase& c)
{
    nlohmann::json explanations = nlohmann::json::array();
    for (const auto& e : c.explanations) {
        nlohmann::json diffs = nlohmann::json::array();
        for (const auto& d : e.differences)
            diffs.push_back({{"radius", d.radius},
                             {"count", d.count},
                             {"reason", d.reason},
                             {"q", d.q},
                             {"contribution", d.contribution}});
        explanations.push_back({{"function", function_name(e.root.function)},
                                {"k", e.root.k},
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
    std::string head = nlohmann::json{{"lattice", c.lattice},
                                      {"mode", c.mode},
                                      {"kernel", c.kernel_label},
                                      {"volume_coefficient", c.ap_name},
                                      {"a_p", c.a_p},
                                      {"roots", scan["roots"]},
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
        comparison.push_back(
            {{"reference", r.reference},
             {"function", r.function ? nlohmann::json(function_name(*r.function)) : nlohmann::json("none")},
             {"computed", r.computed ? root_json(*r.computed) : nlohmann::json(nullptr)},
             {"compared", r.compared},
             {"differs_in", r.differing},
             {"status", status_name(r.status)},
             {"note", r.note}});
    return comparison;
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
    w.print("\n ],\n \"comparison\": {}", comparison_json(results).dump(1));
    for (std::size_t i = 0; i < section_table().size(); ++i) { // a section the study has not: an empty list
        const auto& section = results.sections[i];
        w.print(",\n \"{}\": {}", section_table()[i].key,
                (section ? section->json(study) : nlohmann::json::array()).dump(1));
    }
    w.text("\n}\n");
}

} // namespace sphkern
