#include "study/reproduce.hpp"

#include "study/results_writer.hpp"
#include "study/sections/section_table.hpp"
#include "study/study_runner.hpp"
#include "support/io/json_input.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sphkern {

namespace {

constexpr double agreement = 1e-9;

void compare_values(const nlohmann::json& a, const nlohmann::json& b, const std::string& path, std::size_t limit,
                    NumberComparison& out)
{
    auto differ = [&](const std::string& what) {
        ++out.differing;
        if (out.first.size() < limit) out.first.push_back((path.empty() ? "/" : path) + ": " + what);
    };
    if (a.is_number() && b.is_number()) {
        ++out.compared;
        const double x = a.get<double>(), y = b.get<double>();
        if (!(std::abs(x - y) <= agreement * std::max({1.0, std::abs(x), std::abs(y)})))
            differ(fmt::format("recorded {:.17g}, now {:.17g}", x, y));
        return;
    }
    if (a.type() != b.type()) return differ("recorded " + a.dump().substr(0, 60) + ", now " + b.dump().substr(0, 60));
    if (a.is_array()) {
        if (a.size() != b.size()) return differ(fmt::format("recorded {} entries, now {}", a.size(), b.size()));
        for (std::size_t i = 0; i < a.size(); ++i)
            compare_values(a[i], b[i], path + "/" + std::to_string(i), limit, out);
    } else if (a.is_object()) {
        for (const auto& [key, value] : a.items()) {
            if (!b.contains(key)) differ("\"" + key + "\" is no longer there");
            else compare_values(value, b[key], path + "/" + key, limit, out);
        }
        for (const auto& [key, value] : b.items())
            if (!a.contains(key)) differ("\"" + key + "\" is new");
    } else if (a != b) {
        differ("recorded " + a.dump().substr(0, 60) + ", now " + b.dump().substr(0, 60));
    }
}

std::string entry_name(const nlohmann::json& entry)
{
    return entry.value("label", entry.value("name", std::string("?")));
}

void changed_list(const nlohmann::json& recorded, const nlohmann::json& now, const std::string& what,
                  std::vector<std::string>& out)
{
    if (!recorded.is_array() || !now.is_array() || recorded.size() != now.size()) {
        out.push_back(what + ": the list is not the one recorded");
        return;
    }
    for (std::size_t i = 0; i < recorded.size(); ++i)
        for (const char* key : {"sha256", "parameters", "definition", "expression", "support"})
            if (recorded[i].value(key, nlohmann::json()) != now[i].value(key, nlohmann::json()))
                out.push_back(fmt::format("{} {}: its {} is not the one recorded ({})", what, entry_name(recorded[i]),
                                          key, now[i].value("file", now[i].value("source", std::string()))));
}

} // namespace

Study study_from_results(const nlohmann::json& recorded, const std::string& results_file)
{
    JsonNode root(recorded, results_file);
    root.expect_object();
    const auto file = root.at("study_file").string();
    root.at("study").expect_object();
    return parse_study(recorded.at("study"), file, StudyOrigin{results_file, "/study"});
}

std::vector<std::string> changed_inputs(const nlohmann::json& recorded, const nlohmann::json& now)
{
    std::vector<std::string> out;
    if (!recorded.is_object()) return {"the results file records no inputs (written by an older sphkern)"};
    const auto study_then = recorded.value("study", nlohmann::json::object()).value("sha256", std::string());
    const auto study_now = now.value("study", nlohmann::json::object()).value("sha256", std::string());
    if (study_then != study_now) out.push_back("the study file is not the one recorded (its SHA-256 differs)");
    changed_list(recorded.value("kernels", nlohmann::json()), now.value("kernels", nlohmann::json()), "kernel", out);
    changed_list(recorded.value("lattices", nlohmann::json()), now.value("lattices", nlohmann::json()), "lattice", out);
    return out;
}

NumberComparison compare_result_numbers(const nlohmann::json& recorded, const nlohmann::json& now, std::size_t limit)
{
    NumberComparison out;
    std::vector<std::string> parts = {"cases", "comparison"};
    for (const auto& kind : section_table()) parts.push_back(kind.key);
    for (const auto& part : parts)
        compare_values(recorded.value(part, nlohmann::json()), now.value(part, nlohmann::json()), "/" + part, limit,
                       out);
    return out;
}

Reproduction reproduce_study(const std::string& file, KernelRegistry& registry)
{
    const auto recorded = read_json_file(file);
    Study study = study_from_results(recorded, file);
    StudyResults results = run_study(study, registry);
    for (const auto& line : changed_inputs(recorded.value("inputs", nlohmann::json()), results.inputs))
        spdlog::warn("{}: {}", file, line);
    std::ostringstream text;
    write_study_results_json(text, study, results);
    const auto comparison = compare_result_numbers(recorded, nlohmann::json::parse(text.str()), 10);
    if (comparison.differing == 0)
        return {true, fmt::format("reproduced: all {} numbers of {} agree within a relative 1e-9\n",
                                  comparison.compared, file)};
    std::string out = fmt::format("not reproduced: {} of {} numbers of {} differ; the first:\n", comparison.differing,
                                  comparison.compared, file);
    for (const auto& line : comparison.first) out += fmt::format("  {}\n", line);
    return {false, out};
}

} // namespace sphkern
