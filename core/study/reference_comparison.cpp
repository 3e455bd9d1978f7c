#include "study/reference_comparison.hpp"

#include "support/error.hpp"

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
void compare_values(const ReferenceRow& row, const Root& computed, double tolerance, ComparisonRow& c)
{
    c.compared = {"k"};
    if (std::abs(computed.k - row.k) > tolerance) c.differing.push_back("k");
    const std::pair<const char*, std::optional<double>> printed[] = {{"eps_rho", row.eps_rho},
                                                                     {"eps_gradp", row.eps_gradp}};
    for (const auto& [key, v] : printed) {
        if (!v) continue; // the paper prints no number ("> 1"): nothing to compare
        c.compared.push_back(key);
        const double value = std::string(key) == "eps_rho" ? computed.values.eps_rho : computed.values.eps_gradp;
        if (!(std::abs(value - *v) <= tolerance)) c.differing.push_back(key);
    }
}

// Whether the reference declares an erratum for one value ("erratum_<key>").
bool declared_erratum(const ReferenceRow& row, const std::string& key)
{
    return (key == "eps_rho" && row.erratum_eps_rho) || (key == "eps_gradp" && row.erratum_eps_gradp);
}

// Reproduced only when nothing differs; an erratum when every difference is one the
// reference declares ("erratum" covers the whole row, "erratum_<key>" one value).
ComparisonStatus comparison_status(const ReferenceRow& row, const std::vector<std::string>& differing)
{
    if (differing.empty()) return ComparisonStatus::reproduced;
    if (row.erratum) return ComparisonStatus::erratum;
    for (const auto& key : differing)
        if (!declared_erratum(row, key)) return ComparisonStatus::differs;
    return ComparisonStatus::erratum;
}

// A row the paper finds no root for: reproduced when the case has none either.
ComparisonRow compare_no_root(const ReferenceRow& row, const StudyCase& match)
{
    ComparisonRow c;
    c.reference = row.published;
    c.kernel = row.kernel;
    const bool none = match.scan.roots.empty();
    if (!none) c.differing = {"roots"};
    c.status = none ? ComparisonStatus::reproduced : ComparisonStatus::differs;
    c.note = none ? "no root in the interval" : "sphkern finds roots in the interval";
    return c;
}

ComparisonRow compare_row(const ReferenceRow& row, const StudyCase& match, double tolerance)
{
    if (row.no_root) return compare_no_root(row, match);
    ComparisonRow c;
    c.reference = row.published;
    c.kernel = row.kernel;
    const double k = row.k;
    const auto function = row.eps_gradp && *row.eps_gradp == 0 ? ErrorFunction::gradp : ErrorFunction::rho;
    c.function = function;
    for (const auto& r : match.scan.roots)
        if (r.function == function && (!c.computed || std::abs(r.k - k) < std::abs(c.computed->k - k))) c.computed = r;
    if (!c.computed || std::abs(c.computed->k - k) > 0.05) {
        c.computed.reset();
        c.differing = {"k"};
        c.note = std::string("no root of eps_") + function_name(function) + " near this k";
    } else {
        compare_values(row, *c.computed, tolerance, c);
    }
    c.status = comparison_status(row, c.differing);
    if (row.erratum) c.note = *row.erratum;
    if (row.erratum_eps_gradp && c.status == ComparisonStatus::erratum) c.note = "eps_gradP: " + *row.erratum_eps_gradp;
    if (row.erratum_eps_rho && c.status == ComparisonStatus::erratum) c.note = "eps_rho: " + *row.erratum_eps_rho;
    return c;
}

} // namespace

void compare_with_reference(const ReferenceTable& table, StudyResults& results)
{
    results.reference = table.document;
    results.tolerance = table.tolerance;
    for (const auto& row : table.rows) {
        const StudyCase* match = find_case(results, {table.lattice_index, row.kernel_index,
                                                     table.volume_coefficient_index, table.mode_index});
        if (!match) fail_input(table.file + ": " + row.json_path + ": the study has no case " + row.kernel);
        results.comparison.push_back(compare_row(row, *match, results.tolerance));
    }
}

} // namespace sphkern
