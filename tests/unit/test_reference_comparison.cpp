// The comparison with a reference table: a row is reproduced only when k and every
// printed error agree within the tolerance; otherwise its status says what differs.
#include "study/reference_comparison.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <unistd.h>

using namespace sphkern;

namespace {

Root root(ErrorFunction f, double k, double rho, double gradp)
{
    Root r{f, k, {}, k};
    r.values.eps_rho = rho;
    r.values.eps_gradp = gradp;
    return r;
}

// One case with the given roots, compared with a reference of the given rows.
StudyResults compare(const std::vector<Root>& roots, const std::string& rows)
{
    auto file = std::filesystem::temp_directory_path() / ("sphkern-reference-" + std::to_string(::getpid()) + ".json");
    std::ofstream(file) << R"({"source": "test", "lattice": "L", "volume_coefficient": "voronoi", "mode": "paper",
                              "tolerance": 1e-4, "rows": [)"
                        << rows << "]}";
    auto table = read_reference_table(file);
    resolve_reference_table(table, {{"L"}, {"paper"}, {"voronoi"}, {"K"}});
    StudyResults results;
    StudyCase c;
    // Moved in, not assigned from literals: GCC 12 warns falsely (-Wrestrict) on the latter.
    c.lattice = std::string("L");
    c.mode = std::string("paper");
    c.ap_name = std::string("voronoi");
    c.kernel = std::string("K");
    c.scan.roots = roots;
    results.cases.push_back(c);
    compare_with_reference(table, results);
    std::filesystem::remove(file);
    return results;
}

} // namespace

TEST_CASE("a comparison row is reproduced only if every printed value agrees")
{
    const auto gradp_root = root(ErrorFunction::gradp, 1.0, 0.00076, 0.0);
    // Everything within 1e-4.
    auto r = compare({gradp_root}, R"({"kernel": "K", "k": 1.00005, "eps_rho": 0.0007, "eps_gradp": 0})");
    REQUIRE(r.comparison.size() == 1);
    CHECK(r.comparison[0].status == ComparisonStatus::reproduced);
    CHECK(r.comparison[0].compared == std::vector<std::string>{"k", "eps_rho", "eps_gradp"});
    CHECK(r.comparison[0].differing.empty());
    // k agrees, eps_rho does not: differs, naming eps_rho.
    r = compare({gradp_root}, R"({"kernel": "K", "k": 1.0, "eps_rho": 0.0010, "eps_gradp": 0})");
    CHECK(r.comparison[0].status == ComparisonStatus::differs);
    CHECK(r.comparison[0].differing == std::vector<std::string>{"eps_rho"});
    // The rho root's printed eps_gradP is -0.00331 and the computed -1: an erratum only where the reference says so.
    const auto rho_root = root(ErrorFunction::rho, 0.99963, 0.0, -1.0);
    r = compare({rho_root}, R"({"kernel": "K", "k": 0.99963, "eps_rho": 0, "eps_gradp": -0.00331})");
    CHECK(r.comparison[0].status == ComparisonStatus::differs);
    CHECK(r.comparison[0].differing == std::vector<std::string>{"eps_gradp"});
    r = compare({rho_root},
                R"({"kernel": "K", "k": 0.99963, "eps_rho": 0, "eps_gradp": -0.00331, "erratum_eps_gradp": "why"})");
    CHECK(r.comparison[0].status == ComparisonStatus::erratum);
    CHECK(r.comparison[0].note == "eps_gradP: why");
    // An erratum for one value does not excuse another.
    r = compare({rho_root},
                R"({"kernel": "K", "k": 0.9990, "eps_rho": 0, "eps_gradp": -0.00331, "erratum_eps_gradp": "why"})");
    CHECK(r.comparison[0].status == ComparisonStatus::differs);
    CHECK(r.comparison[0].differing == std::vector<std::string>{"k", "eps_gradp"});
    // A value the paper prints as no number is not compared.
    r = compare({rho_root},
                R"({"kernel": "K", "k": 0.99963, "eps_rho": 0, "eps_gradp": null, "printed_eps_gradp": ">> 1"})");
    CHECK(r.comparison[0].status == ComparisonStatus::reproduced);
    CHECK(r.comparison[0].compared == std::vector<std::string>{"k", "eps_rho"});
}
