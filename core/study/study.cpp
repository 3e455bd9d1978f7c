#include "study/study.hpp"

#include "study/study_error.hpp"
#include "support/text/printable_text.hpp"

#include "study/sections/section_table.hpp"
#include "support/error.hpp"
#include "support/io/file_spec.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/json_input.hpp"
#include "support/process/work_budget.hpp"
#include "support/text/value_checks.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>

namespace sphkern {
namespace fs = std::filesystem;

bool StudyMode::continues(const std::string& kernel) const
{
    return continue_all ||
           std::find(continue_kernels.begin(), continue_kernels.end(), kernel) != continue_kernels.end();
}

const std::vector<double>* StudyMode::shells_for(double R) const
{
    // Keys are written to a few digits: "2" is the list of a support of 2 within a part in 1e6.
    for (const auto& [support, radii] : shells_by_support)
        if (std::abs(support - R) <= 1e-6 * R) return &radii;
    return nullptr;
}

double StudyVolumeCoefficient::on(const Lattice& lattice) const
{
    return value ? *value : lattice.volume_coefficient(name);
}

std::optional<double> parse_radius(const nlohmann::json& value)
{
    if (value.is_number()) {
        double r = value.get<double>();
        return std::isfinite(r) && r > 0 && r < 1e3 ? std::optional(r) : std::nullopt;
    }
    if (!value.is_string()) return std::nullopt;
    static const std::regex sqrt_form(R"(sqrt\(\s*([0-9]+(\.[0-9]*)?)\s*\))");
    std::smatch match;
    std::string text = value.get<std::string>();
    if (!std::regex_match(text, match, sqrt_form)) return std::nullopt;
    double r = std::sqrt(std::stod(match[1].str()));
    return r > 0 && r < 1e3 ? std::optional(r) : std::nullopt;
}

std::vector<std::string> read_string_list(const JsonNode& node)
{
    node.expect_array(1, 1000);
    std::vector<std::string> items;
    for (std::size_t i = 0; i < node.size(); ++i) items.push_back(node[i].string());
    return items;
}

std::map<std::string, double> read_parameter_values(const JsonNode& set)
{
    set.expect_object();
    std::map<std::string, double> values;
    for (const auto& [name, unused] : set.value().items()) values[name] = set.at(name).number();
    return values;
}

StudyVolumeCoefficient read_volume_coefficient(const JsonNode& item)
{
    StudyVolumeCoefficient ap;
    if (item.is_number()) {
        ap.name = item.value().dump();
        ap.value = item.number();
    } else {
        ap.name = item.string();
        char* end = nullptr;
        const double v = std::strtod(ap.name.c_str(), &end);
        if (*end == '\0') ap.value = v;
    }
    if (ap.value && !(*ap.value > 0 && *ap.value <= 1e6))
        item.error("expected a positive volume coefficient up to 1e6");
    return ap;
}

std::optional<double> read_k_or_best(const JsonNode& node)
{
    if (!node.is_string()) return node.number_in(1e-3, 100);
    if (node.string() != "best") node.error("expected a number or \"best\"");
    return std::nullopt;
}

namespace {

// A name of [a-z0-9_-]: a study's or a mode's.
std::string read_name(const JsonNode& node)
{
    std::string name = node.string();
    if (!is_identifier(name, "-", std::numeric_limits<std::size_t>::max())) node.error("expected a name of [a-z0-9_-]");
    return name;
}

// "shells": {"R": [radius, ...], ...}, keyed by the kernel support R as a number.
std::map<double, std::vector<double>> read_shells(const JsonNode& shells)
{
    shells.expect_object();
    if (shells.value().empty()) shells.error("empty object, expected shell lists keyed by kernel support R");
    std::map<double, std::vector<double>> by_support;
    for (const auto& [key, unused] : shells.value().items()) {
        auto list = shells.at(key);
        char* end = nullptr;
        double R = std::strtod(key.c_str(), &end);
        if (key.empty() || *end != '\0' || !(R > 0) || !std::isfinite(R))
            list.error("key must be a kernel support R such as \"2\"");
        list.expect_array(1, 10000);
        std::vector<double> radii;
        for (std::size_t i = 0; i < list.size(); ++i) {
            auto r = parse_radius(list[i].value());
            if (!r) list[i].error("expected a shell radius in units of d: a positive number or \"sqrt(N)\"");
            radii.push_back(*r);
        }
        if (!by_support.emplace(R, radii).second)
            list.error("a second shell list for R = " + key + ", expected one per R");
    }
    return by_support;
}

StudyMode read_mode(const JsonNode& node)
{
    node.expect_keys({"name", "shells", "continue_past_support"});
    StudyMode mode;
    mode.json_path = node.path();
    mode.name = read_name(node.at("name"));
    if (auto shells = node.find("shells")) mode.shells_by_support = read_shells(*shells);
    if (auto c = node.find("continue_past_support")) {
        if (c->is_boolean()) mode.continue_all = c->boolean();
        else if (c->is_array()) mode.continue_kernels = read_string_list(*c);
        else c->error("expected true, false or an array of kernel names, got " + json_type_name(c->value()));
        if ((mode.continue_all || !mode.continue_kernels.empty()) && mode.shells_by_support.empty())
            c->error("continuing past the support needs explicit \"shells\" in the same mode");
    }
    return mode;
}

StudyKernel read_kernel(const JsonNode& item, const fs::path& file)
{
    StudyKernel k;
    k.json_path = item.path();
    if (item.is_string()) {
        k.spec = item.string();
    } else if (item.is_object()) {
        item.expect_keys({"kernel", "set"});
        k.spec = item.at("kernel").string();
        if (auto set = item.find("set")) k.parameters = read_parameter_values(*set);
    } else {
        item.error("expected a kernel name, a plugin file or {\"kernel\": ..., \"set\": {...}}, got " +
                   json_type_name(item.value()));
    }
    k.spec = resolve_beside(k.spec, file, kernel_file_extensions);
    return k;
}

} // namespace

Study read_study(const fs::path& file) { return parse_study(read_json_file(file), file); }

namespace {

// Each field has its own limit, but their product is the work: bounded as a whole,
// before any of it is done (a curve point costs about 200 bytes of results).
void check_study_budget(const Study& study, const JsonNode& root)
{
    auto refuse = [&](const std::string& what, double amount, double limit) {
        root.error("the study " + over_budget(what, amount, limit));
    };
    const double cases = double(study.kernels.size()) * double(study.lattices.size()) *
                         double(study.volume_coefficients.size()) * double(study.modes.size());
    if (cases * study.samples > max_study_curve_points)
        refuse("kernels x lattices x volume_coefficients x modes x k samples", cases * study.samples,
               max_study_curve_points);
    for (const auto& section : study.sections)
        if (section) section->check_budget(study, root);
}

} // namespace

namespace {

std::vector<StudyVolumeCoefficient> read_volume_coefficients(const JsonNode& list)
{
    list.expect_array(1, 100);
    std::vector<StudyVolumeCoefficient> coefficients;
    for (std::size_t i = 0; i < list.size(); ++i) coefficients.push_back(read_volume_coefficient(list[i]));
    return coefficients;
}

// "k": {"min", "max", "samples", "axis"}: the window on its axis.
void read_window(const JsonNode& k, Study& study)
{
    k.expect_keys({"min", "max", "samples", "axis"});
    if (auto v = k.find("min")) study.k_min = v->number();
    if (auto v = k.find("max")) study.k_max = v->number();
    if (auto v = k.find("samples")) study.samples = static_cast<int>(v->integer_in(2, 100000));
    if (auto v = k.find("axis")) {
        const std::string name = v->string();
        study.axis = at_study_path(v->file(), v->path(), [&] { return parse_axis(name, "axis"); });
    }
    at_study_path(k.file(), k.path(), [&] {
        if (study.axis == Axis::k) check_k_interval(study.k_min, study.k_max, ValueSource::argument("k interval"));
        else if (!(study.k_min > 0 && study.k_min < study.k_max && study.k_max <= 1e5))
            fail_input(std::string("the window on the ") + axis_name(study.axis) + " axis needs 0 < min < max");
    });
}

// "sites": "all" (empty) or the indices into every lattice's motif.
std::optional<std::vector<int>> read_sites(const JsonNode& sites)
{
    if (sites.is_string()) {
        if (sites.string() != "all") sites.error("expected \"all\" or an array of site indices");
        return std::nullopt;
    }
    const std::size_t n = sites.expect_array(1, 64);
    std::vector<int> list;
    for (std::size_t i = 0; i < n; ++i) list.push_back(static_cast<int>(sites[i].integer_in(0, 63)));
    return list;
}

std::vector<StudyMode> read_modes(const JsonNode& modes)
{
    modes.expect_array(1, 20);
    std::vector<StudyMode> list;
    for (std::size_t i = 0; i < modes.size(); ++i) {
        list.push_back(read_mode(modes[i]));
        for (std::size_t j = 0; j + 1 < list.size(); ++j)
            if (list[j].name == list.back().name)
                modes[i].at("name").error("duplicate mode name \"" + list.back().name + "\"");
    }
    return list;
}

// "compare_with": a table beside the study or shipped in share/reference, read and checked now.
ReferenceTable read_compare_with(const JsonNode& c, const fs::path& file)
{
    fs::path reference = c.string();
    if (reference.is_relative()) {
        fs::path beside = file.parent_path() / reference;
        reference = fs::exists(beside) ? beside : data_folder("reference") / reference;
    }
    if (!fs::is_regular_file(reference))
        c.error("no reference table \"" + c.string() + "\" beside the study or in share/reference");
    return read_reference_table(reference);
}

// The kernels, lattices and volume coefficients: what every section is run over.
void read_cases(const JsonNode& root, const fs::path& file, Study& study)
{
    auto kernels = root.at("kernels");
    kernels.expect_array(1, 1000);
    for (std::size_t i = 0; i < kernels.size(); ++i) study.kernels.push_back(read_kernel(kernels[i], file));
    study.lattices = read_string_list(root.at("lattices"));
    for (auto& l : study.lattices) l = resolve_beside(l, file, {".json"});
    if (auto ap = root.find("volume_coefficients")) study.volume_coefficients = read_volume_coefficients(*ap);
    else study.volume_coefficients = {{"voronoi", std::nullopt}};
}

// The optional sections, each read whole by its row of the table.
void read_sections(const JsonNode& root, const fs::path& file, Study& study)
{
    for (const auto& kind : section_table()) {
        const auto node = root.find(kind.key);
        study.sections.push_back(node ? kind.read(*node, file) : nullptr);
    }
}

// The study file's keys: the spine's, then one per section.
std::vector<std::string> study_keys()
{
    std::vector<std::string> keys = {"$schema", "name",    "title", "kernels",      "lattices", "volume_coefficients",
                                     "k",       "epsilon", "modes", "compare_with", "plots",    "sites",
                                     "lateral"};
    for (const auto& kind : section_table()) keys.push_back(kind.key);
    return keys;
}

} // namespace

Study parse_study(nlohmann::json document, const fs::path& file, std::optional<StudyOrigin> origin)
{
    Study study;
    // Relative paths in the study are read from its folder: anchored on the absolute file, they
    // are absolute, and so is the study_file results.json records (run --reproduce from anywhere).
    const fs::path anchor = fs::absolute(file).lexically_normal();
    study.file = anchor.string();
    study.origin = origin ? *origin : StudyOrigin{file.string(), ""};
    study.document = std::move(document);
    JsonNode root(study.document, study.origin.file, study.origin.pointer);
    root.expect_keys(study_keys());
    study.name = read_name(root.at("name"));
    study.title = root.find("title") ? printable_text(root.at("title").string()) : study.name;
    read_cases(root, anchor, study);
    if (auto k = root.find("k")) read_window(*k, study);
    if (auto e = root.find("epsilon")) {
        study.epsilon = e->number();
        if (study.epsilon <= 0 || study.epsilon >= 1) e->error("expected a tolerance in (0, 1)");
    }
    if (auto sites = root.find("sites")) study.sites = read_sites(*sites);
    if (auto lateral = root.find("lateral")) study.lateral = lateral->boolean();
    if (auto modes = root.find("modes")) study.modes = read_modes(*modes);
    else study.modes.push_back({"default", {}, false, {}, "/modes"});
    if (auto c = root.find("compare_with")) study.reference = read_compare_with(*c, anchor);
    if (auto p = root.find("plots")) study.plots = p->boolean();
    read_sections(root, anchor, study);
    check_study_budget(study, root);
    return study;
}

ValueSource study_source(const Study& study, const std::string& pointer)
{
    return ValueSource::json(study.origin.file, study.origin.pointer + pointer);
}

} // namespace sphkern
