#include "study/study.hpp"

#include "support/printable_text.hpp"

#include "analysis/resolution_axis.hpp"

#include "analysis/results_json.hpp"
#include "analysis/surface_profile.hpp"
#include "support/error.hpp"
#include "support/file_spec.hpp"
#include "support/install_paths.hpp"
#include "support/json_input.hpp"
#include "support/work_budget.hpp"
#include "stability/stability_budget.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <regex>

namespace sphkern {
namespace fs = std::filesystem;

bool StudyMode::continues(const std::string& kernel) const
{
    return continue_all || std::find(continue_kernels.begin(), continue_kernels.end(), kernel) != continue_kernels.end();
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

namespace {

const std::vector<std::string> kernel_file_extensions = {".so", ".json"};

std::vector<std::string> string_list(const JsonNode& node)
{
    node.expect_array(1, 1000);
    std::vector<std::string> items;
    for (std::size_t i = 0; i < node.size(); ++i) items.push_back(node[i].string());
    return items;
}

StudyMode read_mode(const JsonNode& node)
{
    node.expect_keys({"name", "shells", "continue_past_support"});
    StudyMode mode;
    mode.json_path = node.path();
    mode.name = node.at("name").string();
    if (mode.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos)
        node.at("name").error("expected a name of [a-z0-9_-]");
    if (auto shells = node.find("shells")) {
        shells->expect_object();
        if (shells->value().empty()) shells->error("empty object, expected shell lists keyed by kernel support R");
        for (const auto& [key, unused] : shells->value().items()) {
            auto list = shells->at(key);
            char* end = nullptr;
            double R = std::strtod(key.c_str(), &end);
            if (key.empty() || *end != '\0' || !(R > 0))
                list.error("key must be a kernel support R such as \"2\"");
            list.expect_array(1, 10000);
            std::vector<double> radii;
            for (std::size_t i = 0; i < list.size(); ++i) {
                auto r = parse_radius(list[i].value());
                if (!r) list[i].error("expected a shell radius in units of d: a positive number or \"sqrt(N)\"");
                radii.push_back(*r);
            }
            mode.shells_by_support[key] = radii;
        }
    }
    if (auto c = node.find("continue_past_support")) {
        if (c->is_boolean()) mode.continue_all = c->boolean();
        else if (c->is_array()) mode.continue_kernels = string_list(*c);
        else c->error("expected true, false or an array of kernel names, got " + json_type_name(c->value()));
        if ((mode.continue_all || !mode.continue_kernels.empty()) && mode.shells_by_support.empty())
            c->error("continuing past the support needs explicit \"shells\" in the same mode");
    }
    return mode;
}

// "set": {"parameter": value, ...}
std::map<std::string, double> parameter_values(const JsonNode& set)
{
    set.expect_object();
    std::map<std::string, double> values;
    for (const auto& [name, unused] : set.value().items()) values[name] = set.at(name).number();
    return values;
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
        if (auto set = item.find("set")) k.parameters = parameter_values(*set);
    } else {
        item.error("expected a kernel name, a plugin file or {\"kernel\": ..., \"set\": {...}}, got " +
                   json_type_name(item.value()));
    }
    k.spec = resolve_beside(k.spec, file, kernel_file_extensions);
    return k;
}

// A k given as a number, or "best" (empty): each kernel's best k of condition (22).
std::optional<double> k_or_best(const JsonNode& node)
{
    if (!node.is_string()) return node.number_in(1e-3, 100);
    if (node.string() != "best") node.error("expected a number or \"best\"");
    return std::nullopt;
}

StudySweep read_sweep(const JsonNode& node, const fs::path& file)
{
    node.expect_keys({"kernel", "set", "parameter", "range", "samples"});
    StudySweep sweep;
    sweep.json_path = node.path();
    sweep.kernel = resolve_beside(node.at("kernel").string(), file, kernel_file_extensions);
    if (auto set = node.find("set")) sweep.parameters = parameter_values(*set);
    sweep.parameter = node.at("parameter").string();
    auto range = node.at("range");
    range.expect_array(2, 2);
    sweep.min = range[0].number();
    sweep.max = range[1].number();
    if (!(sweep.min < sweep.max)) range.error("expected [min, max] with min < max");
    if (auto n = node.find("samples")) sweep.samples = static_cast<int>(n->integer_in(3, 1000));
    return sweep;
}

StudySurface read_surface(const JsonNode& node)
{
    node.expect_keys({"k", "layers", "forms", "volume_coefficient"});
    StudySurface surface;
    if (auto k = node.find("k")) surface.k = k_or_best(*k);
    if (auto layers = node.find("layers")) surface.layers = static_cast<int>(layers->integer_in(1, 1000));
    if (auto forms = node.find("forms")) {
        surface.forms = string_list(*forms);
        for (std::size_t i = 0; i < surface.forms.size(); ++i) {
            try {
                parse_gradient_form(surface.forms[i]);
            } catch (const Error& e) {
                (*forms)[i].error(e.what());
            }
        }
    }
    if (auto ap = node.find("volume_coefficient"))
        surface.volume_coefficient = ap->is_number() ? ap->value().dump() : ap->string();
    return surface;
}

StudyStability read_stability(const JsonNode& node)
{
    node.expect_keys({"gamma", "k", "grid", "dispersion_k", "path_points", "horizon", "h_model"});
    StudyStability stability;
    if (auto gamma = node.find("gamma")) stability.gamma = gamma->number_in(1e-6, 1e6);
    if (auto k = node.find("k")) {
        k->expect_keys({"min", "max", "steps"});
        if (k->find("min") || k->find("max")) {
            stability.k_min = k->at("min").number_in(1e-3, 100);
            stability.k_max = k->at("max").number_in(1e-3, 100);
            if (*stability.k_min >= *stability.k_max) k->at("max").error("expected max > min");
        }
        if (auto steps = k->find("steps")) stability.steps = static_cast<int>(steps->integer_in(1, 2000));
    }
    if (auto grid = node.find("grid")) stability.grid = static_cast<int>(grid->integer_in(2, 200));
    if (auto k = node.find("dispersion_k")) stability.path_k = k_or_best(*k);
    if (auto points = node.find("path_points")) stability.path_points = static_cast<int>(points->integer_in(10, 5000));
    if (auto horizon = node.find("horizon")) stability.horizon = horizon->number_in(1e-6, 1e12);
    if (auto model = node.find("h_model")) {
        stability.h_model = model->text();
        if (stability.h_model != "fixed" && stability.h_model != "adaptive")
            model->error("expected \"fixed\" or \"adaptive\"");
    }
    return stability;
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
    double sweep_points = 0;
    for (const auto& s : study.sweeps)
        sweep_points += double(study.lattices.size()) * s.samples * std::min(study.samples, 201);
    if (sweep_points > max_study_sweep_points)
        refuse("lattices x sweep samples x k samples, over all sweeps", sweep_points, max_study_sweep_points);
    if (study.surface) {
        double layers = double(study.kernels.size()) * double(study.lattices.size()) *
                        double(study.surface->forms.size()) * study.surface->layers;
        if (layers > max_study_surface_layers)
            refuse("kernels x lattices x surface forms x layers", layers, max_study_surface_layers);
    }
    if (study.stability) {
        const double points = double(study.kernels.size()) * double(study.lattices.size()) *
                              stability_wave_vectors(study.stability->steps, study.stability->grid, 0);
        if (points > max_study_stability_points)
            refuse("kernels x lattices x stability k samples x wave vectors", points, max_study_stability_points);
    }
    if (study.particles) {
        const double evaluations = double(study.kernels.size()) * study_particle_evaluations(*study.particles);
        if (evaluations > max_study_particle_evaluations)
            refuse("kernels x particles x N_H values, over all particle sources", evaluations, max_study_particle_evaluations);
    }
}

} // namespace

Study parse_study(nlohmann::json document, const fs::path& file)
{
    Study study;
    study.file = file.string();
    study.document = std::move(document);
    JsonNode root(study.document, study.file);
    root.expect_keys({"$schema", "name", "title", "kernels", "lattices", "volume_coefficients", "k", "epsilon", "modes",
                      "compare_with", "plots", "surface", "sweeps", "sites", "lateral", "stability", "particles"});
    study.name = root.at("name").string();
    if (study.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos)
        root.at("name").error("expected a name of [a-z0-9_-]");
    study.title = root.find("title") ? printable_text(root.at("title").string()) : study.name;

    auto kernels = root.at("kernels");
    kernels.expect_array(1, 1000);
    for (std::size_t i = 0; i < kernels.size(); ++i) study.kernels.push_back(read_kernel(kernels[i], file));
    study.lattices = string_list(root.at("lattices"));
    for (auto& l : study.lattices) l = resolve_beside(l, file, {".json"});

    if (auto ap = root.find("volume_coefficients")) {
        ap->expect_array(1, 100);
        for (std::size_t i = 0; i < ap->size(); ++i) {
            auto item = (*ap)[i];
            if (item.is_number()) {
                double v = item.number();
                if (v <= 0 || v > 1e6) item.error("expected a positive volume coefficient up to 1e6");
                study.volume_coefficients.push_back(item.value().dump());
            } else {
                study.volume_coefficients.push_back(item.string());
            }
        }
    } else {
        study.volume_coefficients = {"voronoi"};
    }

    if (auto k = root.find("k")) {
        k->expect_keys({"min", "max", "samples", "axis"});
        if (auto v = k->find("min")) study.k_min = v->number();
        if (auto v = k->find("max")) study.k_max = v->number();
        if (auto v = k->find("samples")) study.samples = static_cast<int>(v->integer_in(2, 100000));
        if (auto v = k->find("axis")) {
            study.axis = v->string();
            try {
                parse_axis(study.axis, "axis");
            } catch (const Error& e) {
                v->error(e.what());
            }
        }
        try {
            if (study.axis == "k") check_k_interval(study.k_min, study.k_max, "k interval");
            else if (!(study.k_min > 0 && study.k_min < study.k_max && study.k_max <= 1e5))
                fail_input("the window on the " + study.axis + " axis needs 0 < min < max");
        } catch (const Error& e) {
            k->error(e.what());
        }
    }
    if (auto e = root.find("epsilon")) {
        study.epsilon = e->number();
        if (study.epsilon <= 0 || study.epsilon >= 1) e->error("expected a tolerance in (0, 1)");
    }
    if (auto sites = root.find("sites")) {
        if (sites->is_string()) {
            if (sites->string() != "all") sites->error("expected \"all\" or an array of site indices");
        } else {
            const std::size_t n = sites->expect_array(1, 64);
            std::vector<int> list;
            for (std::size_t i = 0; i < n; ++i) list.push_back(static_cast<int>((*sites)[i].integer_in(0, 63)));
            study.sites = list;
        }
    }
    if (auto lateral = root.find("lateral")) study.lateral = lateral->boolean();
    if (auto modes = root.find("modes")) {
        modes->expect_array(1, 20);
        for (std::size_t i = 0; i < modes->size(); ++i) {
            study.modes.push_back(read_mode((*modes)[i]));
            for (std::size_t j = 0; j + 1 < study.modes.size(); ++j)
                if (study.modes[j].name == study.modes.back().name)
                    (*modes)[i].at("name").error("duplicate mode name \"" + study.modes.back().name + "\"");
        }
    } else {
        study.modes.push_back({"default", {}, false, {}, "/modes"});
    }
    if (auto c = root.find("compare_with")) {
        fs::path reference = c->string();
        if (reference.is_relative()) {
            fs::path beside = file.parent_path() / reference;
            reference = fs::exists(beside) ? beside : data_folder("reference") / reference;
        }
        if (!fs::is_regular_file(reference)) c->error("no reference table \"" + c->string() + "\" beside the study or in share/reference");
        study.compare_with = reference;
    }
    if (auto p = root.find("plots")) study.plots = p->boolean();
    if (auto sweeps = root.find("sweeps")) {
        sweeps->expect_array(1, 20);
        for (std::size_t i = 0; i < sweeps->size(); ++i) study.sweeps.push_back(read_sweep((*sweeps)[i], file));
    }
    if (auto node = root.find("surface")) study.surface = read_surface(*node);
    if (auto node = root.find("stability")) study.stability = read_stability(*node);
    if (auto node = root.find("particles")) study.particles = read_study_particles(*node, file);
    check_study_budget(study, root);
    return study;
}

} // namespace sphkern
