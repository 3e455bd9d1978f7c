#include "study/reference_comparison.hpp"

#include "support/error.hpp"
#include "support/json_input.hpp"

#include <algorithm>
#include <cmath>

namespace sphkern {

const char* status_name(ComparisonStatus status)
{
    switch (status) {
    case ComparisonStatus::reproduced: return "reproduced";
    case ComparisonStatus::differs: return "differs";
    case ComparisonStatus::erratum: return "erratum";
    }
    return "differs";
}

namespace {

// Every value the row prints as a number, against the matching root: k and both errors.
void compare_values(const JsonNode& row, const Root& computed, double tolerance, ComparisonRow& c)
{
    c.compared = {"k"};
    if (std::abs(computed.k - row.at("k").number()) > tolerance) c.differing.push_back("k");
    for (const char* key : {"eps_rho", "eps_gradp"}) {
        const auto& v = row.at(key).value();
        if (!v.is_number()) continue; // the paper prints no number ("> 1"): nothing to compare
        c.compared.push_back(key);
        const double value = std::string(key) == "eps_rho" ? computed.values.eps_rho : computed.values.eps_gradp;
        if (!(std::abs(value - v.get<double>()) <= tolerance)) c.differing.push_back(key);
    }
}

// Reproduced only when nothing differs; an erratum when every difference is one the
// reference declares ("erratum" covers the whole row, "erratum_<key>" one value).
ComparisonStatus comparison_status(const JsonNode& row, const std::vector<std::string>& differing)
{
    if (differing.empty()) return ComparisonStatus::reproduced;
    if (row.find("erratum")) return ComparisonStatus::erratum;
    for (const auto& key : differing)
        if (!row.find("erratum_" + key)) return ComparisonStatus::differs;
    return ComparisonStatus::erratum;
}

} // namespace

void compare_with_reference(const Study& study, StudyResults& results)
{
    auto document = read_json_file(*study.compare_with);
    JsonNode root(document, study.compare_with->string());
    root.expect_keys({"source", "lattice", "volume_coefficient", "mode", "tolerance", "rows"});
    results.reference = document;
    std::string lattice = root.at("lattice").string(), ap = root.at("volume_coefficient").string(),
                mode = root.at("mode").string();
    results.tolerance = root.find("tolerance") ? root.at("tolerance").number_in(0, 1) : 1e-4;
    auto rows = root.at("rows");
    rows.expect_array(1);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        auto row = rows[i];
        ComparisonRow c;
        c.reference = row.value();
        c.kernel = row.at("kernel").string();
        auto match = std::find_if(results.cases.begin(), results.cases.end(), [&](const StudyCase& s) {
            return s.lattice == lattice && s.mode == mode && s.ap_name == ap && s.kernel == c.kernel;
        });
        if (match == results.cases.end())
            row.error("the study has no case " + c.kernel + " / " + lattice + " / " + ap + " / mode " + mode);
        row.expect_keys({"kernel", "k", "eps_rho", "eps_gradp", "printed_eps_gradp", "no_root", "erratum",
                         "erratum_eps_gradp", "erratum_eps_rho"});
        for (const char* key : {"printed_eps_gradp", "erratum", "erratum_eps_gradp", "erratum_eps_rho"})
            if (auto v = row.find(key)) v->string();
        if (auto no_root = row.find("no_root"); no_root && no_root->boolean()) {
            if (!match->scan.roots.empty()) c.differing = {"roots"};
            c.status = match->scan.roots.empty() ? ComparisonStatus::reproduced : ComparisonStatus::differs;
            c.note = match->scan.roots.empty() ? "no root in the interval" : "sphkern finds roots in the interval";
            results.comparison.push_back(c);
            continue;
        }
        double k = row.at("k").number();
        for (const char* key : {"eps_rho", "eps_gradp"}) // a number, or null where the paper prints none
            if (auto v = row.at(key); !v.value().is_null()) v.number();
        const auto& gradp_value = row.at("eps_gradp").value();
        const auto function = gradp_value.is_number() && gradp_value.get<double>() == 0 ? ErrorFunction::gradp
                                                                                        : ErrorFunction::rho;
        c.function = function;
        for (const auto& r : match->scan.roots)
            if (r.function == function && (!c.computed || std::abs(r.k - k) < std::abs(c.computed->k - k)))
                c.computed = r;
        if (!c.computed || std::abs(c.computed->k - k) > 0.05) {
            c.computed.reset();
            c.differing = {"k"};
            c.note = std::string("no root of eps_") + function_name(function) + " near this k";
        } else {
            compare_values(row, *c.computed, results.tolerance, c);
        }
        c.status = comparison_status(row, c.differing);
        if (auto e = row.find("erratum")) c.note = e->string();
        if (auto e = row.find("erratum_eps_gradp"); e && c.status == ComparisonStatus::erratum)
            c.note = "eps_gradP: " + e->string();
        if (auto e = row.find("erratum_eps_rho"); e && c.status == ComparisonStatus::erratum)
            c.note = "eps_rho: " + e->string();
        results.comparison.push_back(c);
    }
}

} // namespace sphkern
