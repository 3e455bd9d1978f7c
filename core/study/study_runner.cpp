#include "study/study_runner.hpp"

#include "analysis/results_json.hpp"
#include "analysis/resolution_axis.hpp"
#include "analysis/site_errors.hpp"
#include "lattices/lattice.hpp"
#include "support/chunked_writer.hpp"
#include "support/error.hpp"
#include "support/json_input.hpp"
#include "support/interruption.hpp"
#include "support/progress.hpp"

#include <algorithm>
#include <tuple>
#include <cmath>

namespace sphkern {

namespace {

std::string support_key(double R)
{
    std::ostringstream s;
    s << R;
    return s.str();
}

EvaluationMode mode_for(const StudyMode& mode, const Kernel& kernel, const Study& study)
{
    EvaluationMode m;
    if (mode.shells_by_support.empty()) return m;
    auto it = mode.shells_by_support.find(support_key(kernel.support()));
    if (it == mode.shells_by_support.end())
        fail_input(study.file + ": " + mode.json_path + "/shells: no shell list for kernel " + kernel.name() +
                   " with support R = " + support_key(kernel.support()) + ", expected a key \"" +
                   support_key(kernel.support()) + "\"");
    m.shell_radii = it->second;
    m.continue_past_support = mode.continues(kernel.name());
    return m;
}

std::vector<RootExplanation> explain(const HydrostaticErrors& mode, const HydrostaticErrors& automatic,
                                     const RootScan& scan, const RootScan& automatic_scan)
{
    std::vector<RootExplanation> explanations;
    const double R = mode.kernel().support();
    for (const auto& root : scan.roots) {
        bool rho = root.function == "rho";
        RootExplanation e;
        e.root = root;
        auto v = automatic.at(root.k);
        e.default_value = rho ? v.eps_rho : v.eps_gradp;
        for (const auto& r : automatic_scan.roots)
            if (r.function == root.function &&
                (!e.default_root_k || std::abs(r.k - root.k) < std::abs(*e.default_root_k - root.k)))
                e.default_root_k = r.k;
        std::size_t active = mode.active_terms(root.k);
        for (std::size_t i = 0; i < active; ++i) {
            const Shell& s = mode.terms()[i];
            if (s.radius <= R * root.k) continue;
            auto c = mode.shell_contribution(s, root.k);
            e.differences.push_back({s.radius, s.count, "evaluated past R", s.radius / root.k, rho ? c.first : c.second});
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

void compare(const Study& study, StudyResults& results)
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
            c.function = "none";
            c.status = match->scan.roots.empty() ? "reproduced" : "differs";
            c.note = match->scan.roots.empty() ? "no root in the interval" : "sphkern finds roots in the interval";
            results.comparison.push_back(c);
            continue;
        }
        double k = row.at("k").number();
        for (const char* key : {"eps_rho", "eps_gradp"}) // a number, or null where the paper prints none
            if (auto v = row.at(key); !v.value().is_null()) v.number();
        const auto& gradp_value = row.at("eps_gradp").value();
        c.function = gradp_value.is_number() && gradp_value.get<double>() == 0 ? "gradp" : "rho";
        for (const auto& r : match->scan.roots)
            if (r.function == c.function && (!c.computed || std::abs(r.k - k) < std::abs(c.computed->k - k)))
                c.computed = r;
        if (!c.computed || std::abs(c.computed->k - k) > 0.05) {
            c.computed.reset();
            c.status = row.find("erratum") ? "erratum" : "differs";
            c.note = "no root of eps_" + c.function + " near this k";
        } else {
            bool within = std::abs(c.computed->k - k) <= results.tolerance;
            for (const char* key : {"eps_rho", "eps_gradp"}) {
                const auto& v = row.at(key).value();
                if (!v.is_number() || row.find(std::string("erratum_") + key)) continue;
                double computed = std::string(key) == "eps_rho" ? c.computed->values.eps_rho : c.computed->values.eps_gradp;
                within = within && std::abs(computed - v.get<double>()) <= results.tolerance;
            }
            c.status = row.find("erratum") ? "erratum" : within ? "reproduced" : "differs";
        }
        if (auto e = row.find("erratum")) c.note = e->string();
        if (auto e = row.find("erratum_eps_gradp")) c.note = "eps_gradP: " + e->string();
        results.comparison.push_back(c);
    }
}

} // namespace

StudyResults run_study(const Study& study, KernelRegistry& registry)
{
    std::vector<Kernel> kernels;
    for (const auto& k : study.kernels) {
        try {
            kernels.push_back(Kernel(registry.find(k.spec), k.parameters));
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": " + k.json_path + ": " + e.what());
        }
    }
    std::vector<Lattice> lattices;
    for (std::size_t i = 0; i < study.lattices.size(); ++i) {
        try {
            lattices.push_back(load_lattice(study.lattices[i]));
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": /lattices/" + std::to_string(i) + ": " + e.what());
        }
    }
    // One name, one table: two lattices or kernels that print alike would be merged.
    for (std::size_t i = 0; i < lattices.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (lattices[i].name == lattices[j].name)
                fail_input(study.file + ": /lattices/" + std::to_string(i) + ": lattice name \"" + lattices[i].name +
                           "\" is already used by /lattices/" + std::to_string(j) + "; give each lattice its own name");
    for (std::size_t i = 0; i < kernels.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (kernels[i].label() == kernels[j].label())
                fail_input(study.file + ": " + study.kernels[i].json_path + ": kernel \"" + kernels[i].label() +
                           "\" is listed twice (also at " + study.kernels[j].json_path + ")");
    for (std::size_t i = 0; i < kernels.size(); ++i)
        for (const auto& l : lattices)
            try {
                kernels[i].require_dimension(l.dimension, l.name);
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": " + study.kernels[i].json_path + ": " + e.what());
            }

    StudyResults results;
    Progress progress("study " + study.name,
                      lattices.size() * kernels.size() * study.volume_coefficients.size() * study.modes.size());
    for (const auto& lattice : lattices) {
        std::vector<double> aps;
        for (std::size_t i = 0; i < study.volume_coefficients.size(); ++i) {
            try {
                aps.push_back(lattice.volume_coefficient(study.volume_coefficients[i]));
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": /volume_coefficients/" + std::to_string(i) + ": " + e.what());
            }
        }
        const std::vector<int> sites = study.sites ? *study.sites : every_site(lattice);
        try {
            check_sites(lattice, sites, "sites");
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": /sites: " + e.what());
        }
        const AcceptanceRule along{study.epsilon, Direction::gravity, study.lateral};
        const AcceptanceRule every{study.epsilon, Direction::every, study.lateral};
        for (const auto& kernel : kernels)
            for (std::size_t a = 0; a < aps.size(); ++a) {
                double k_min, k_max;
                try {
                    std::tie(k_min, k_max) = k_window(parse_axis(study.axis, "axis"), study.k_min, study.k_max, kernel,
                                                      lattice, sites[0], aps[a], "window");
                } catch (const Error& e) {
                    throw Error(e.code(), study.file + ": /k: " + e.what());
                }
                HydrostaticErrors automatic(kernel, lattice, sites[0], aps[a], lattice.gravity, k_max);
                RootScan automatic_scan = find_roots(automatic, k_min, k_max);
                for (const auto& mode : study.modes) {
                    StudyCase c;
                    c.lattice = lattice.name;
                    c.dimension = lattice.dimension;
                    c.mode = mode.name;
                    c.automatic = mode.is_automatic();
                    c.kernel = kernel.name();
                    c.kernel_label = kernel.label();
                    c.support = kernel.support();
                    c.ap_name = study.volume_coefficients[a];
                    c.a_p = aps[a];
                    c.k_min = k_min;
                    c.k_max = k_max;
                    c.sites = sites;
                    auto errors = errors_per_site(kernel, lattice, sites, aps[a], lattice.gravity, k_max,
                                                  mode_for(mode, kernel, study));
                    for (int i = 0; i < study.samples; ++i) {
                        if (i % 64 == 0) throw_if_interrupted();
                        double k = k_min + (k_max - k_min) * i / (study.samples - 1);
                        c.curve.emplace_back(k, errors[0]->at(k));
                    }
                    c.scan = c.automatic ? automatic_scan : find_roots(*errors[0], k_min, k_max);
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
                    results.cases.push_back(std::move(c));
                    progress.step(kernel.name() + " on " + lattice.name);
                    throw_if_interrupted();
                }
            }
    }
    if (study.surface) {
        const auto& surface = *study.surface;
        const std::string ap_name = surface.volume_coefficient.empty() ? study.volume_coefficients[0] : surface.volume_coefficient;
        for (const auto& lattice : lattices) {
            double a_p;
            try {
                a_p = lattice.volume_coefficient(ap_name);
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": /surface/volume_coefficient: " + e.what());
            }
            for (const auto& kernel : kernels) {
                double k = 0;
                if (surface.k) {
                    k = *surface.k;
                } else { // the best k of condition (22) in the first mode, for this a_p, in the study's window
                    auto [k_min, k_max] = k_window(parse_axis(study.axis, "axis"), study.k_min, study.k_max, kernel,
                                                   lattice, 0, a_p, "window");
                    HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, k_max,
                                             mode_for(study.modes[0], kernel, study));
                    k = evaluate_acceptance(errors, k_min, k_max, study.epsilon).best_k;
                }
                for (const auto& form : surface.forms) {
                    SurfaceCase c{lattice.name, kernel.label(), form, ap_name, a_p, k, {}};
                    try {
                        c.profile = surface_profile(kernel, lattice, 0, a_p, lattice.gravity, k, surface.layers,
                                                    parse_gradient_form(form));
                    } catch (const Error& e) {
                        throw Error(e.code(), study.file + ": /surface: " + e.what());
                    }
                    results.surface.push_back(std::move(c));
                    throw_if_interrupted();
                }
            }
        }
    }
    for (const auto& sweep : study.sweeps) {
        std::optional<Kernel> kernel;
        try {
            kernel.emplace(registry.find(sweep.kernel), sweep.parameters);
        } catch (const Error& e) {
            throw Error(e.code(), study.file + ": " + sweep.json_path + ": " + e.what());
        }
        for (const auto& lattice : lattices) {
            if (!kernel->supports(lattice.dimension)) continue;
            SweepCase c;
            c.lattice = lattice.name;
            c.kernel = kernel->name();
            c.parameter = sweep.parameter;
            c.ap_name = study.volume_coefficients[0];
            c.a_p = lattice.volume_coefficient(c.ap_name);
            // Sweeps keep one k grid per lattice: the window of the sweep's kernel at its declared parameters.
            auto [k_min, k_max] = k_window(parse_axis(study.axis, "axis"), study.k_min, study.k_max, *kernel, lattice,
                                           0, c.a_p, "window");
            DesignProblem problem{&lattice, 0, c.a_p, lattice.gravity, k_min, k_max, sweep.parameter, sweep.min, sweep.max};
            try {
                c.design = design_kernel(*kernel, problem);
            } catch (const Error& e) {
                throw Error(e.code(), study.file + ": " + sweep.json_path + ": " + e.what());
            }
            const int k_samples = std::min(study.samples, 201);
            for (int j = 0; j < k_samples; ++j) c.ks.push_back(k_min + (k_max - k_min) * j / (k_samples - 1));
            for (int i = 0; i < sweep.samples; ++i) {
                throw_if_interrupted();
                double value = sweep.min + (sweep.max - sweep.min) * i / (sweep.samples - 1);
                auto values = sweep.parameters;
                values[sweep.parameter] = value;
                Kernel at(kernel->shared_definition(), values);
                HydrostaticErrors errors(at, lattice, 0, c.a_p, lattice.gravity, k_max);
                c.values.push_back(value);
                c.rho.emplace_back();
                c.gradp.emplace_back();
                for (double k : c.ks) {
                    auto v = errors.at(k);
                    c.rho.back().push_back(v.eps_rho);
                    c.gradp.back().push_back(v.eps_gradp);
                }
            }
            for (const auto& s : c.design.solutions) {
                auto values = sweep.parameters;
                values[sweep.parameter] = s.parameter;
                Kernel designed(kernel->shared_definition(), values);
                HydrostaticErrors errors(designed, lattice, 0, c.a_p, lattice.gravity, k_max);
                c.designed_acceptance.push_back(evaluate_acceptance(errors, k_min, k_max, study.epsilon));
            }
            results.sweeps.push_back(std::move(c));
            throw_if_interrupted();
        }
    }
    if (study.compare_with) compare(study, results);
    return results;
}

nlohmann::json per_site_json(const StudyCase& c, double epsilon)
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : c.per_site) list.push_back(site_roots_json(p, epsilon));
    return list;
}

// Streamed: every part but the curves is a small JSON value; the curves, most of the
// document, are written number by number without building a JSON tree for them.
void write_study_results_json(std::ostream& out, const Study& study, const StudyResults& results)
{
    ChunkedWriter w(out);
    auto number = [&](double v) {
        if (std::isfinite(v)) w.print("{}", v);
        else w.text("null");
    };
    w.print("{{\n \"sphkern_version\": {},\n \"study_file\": {},\n \"study\": {},\n \"cases\": [",
            nlohmann::json(SPHKERN_VERSION).dump(), nlohmann::json(study.file).dump(), study.document.dump());
    for (std::size_t i = 0; i < results.cases.size(); ++i) {
        const auto& c = results.cases[i];
        nlohmann::json explanations = nlohmann::json::array();
        for (const auto& e : c.explanations) {
            nlohmann::json diffs = nlohmann::json::array();
            for (const auto& d : e.differences)
                diffs.push_back({{"radius", d.radius}, {"count", d.count}, {"reason", d.reason}, {"q", d.q},
                                 {"contribution", d.contribution}});
            explanations.push_back({{"function", e.root.function}, {"k", e.root.k},
                                    {"default_value", e.default_value},
                                    {"default_root_k", e.default_root_k ? nlohmann::json(*e.default_root_k) : nullptr},
                                    {"differences", diffs}});
        }
        auto scan = root_scan_json(c.scan);
        std::string head = nlohmann::json{{"lattice", c.lattice}, {"mode", c.mode}, {"kernel", c.kernel_label},
                                          {"volume_coefficient", c.ap_name}, {"a_p", c.a_p}, {"roots", scan["roots"]},
                                          {"jumps", scan["jumps"]},
                                          {"sites", c.sites},
                                          {"acceptance", acceptance_json(c.acceptance, study.epsilon)},
                                          {"acceptance_every_direction", acceptance_json(c.acceptance_every, study.epsilon)},
                                          {"per_site", per_site_json(c, study.epsilon)},
                                          {"explanations", explanations}}
                               .dump();
        head.pop_back(); // the closing brace: the curve follows
        w.text(i ? ",\n  " : "\n  ");
        w.text(head);
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
    nlohmann::json comparison = nlohmann::json::array();
    for (const auto& r : results.comparison)
        comparison.push_back({{"reference", r.reference},
                              {"function", r.function},
                              {"computed", r.computed ? root_json(*r.computed) : nlohmann::json(nullptr)},
                              {"status", r.status},
                              {"note", r.note}});
    nlohmann::json surface = nlohmann::json::array();
    for (const auto& c : results.surface) {
        auto entry = surface_json(c.profile);
        entry.update({{"lattice", c.lattice}, {"kernel", c.kernel_label}, {"form", c.form},
                      {"volume_coefficient", c.ap_name}, {"a_p", c.a_p}, {"k", c.k}});
        surface.push_back(entry);
    }
    nlohmann::json sweeps = nlohmann::json::array();
    for (const auto& c : results.sweeps) {
        nlohmann::json solutions = nlohmann::json::array();
        for (std::size_t i = 0; i < c.design.solutions.size(); ++i) {
            const auto& s = c.design.solutions[i];
            solutions.push_back({{"k", s.k}, {"parameter", s.parameter}, {"eps_rho", s.values.eps_rho},
                                 {"eps_gradp", s.values.eps_gradp}, {"jacobian_condition", s.jacobian_condition},
                                 {"non_negative", s.non_negative},
                                 {"acceptance", acceptance_json(c.designed_acceptance[i], study.epsilon)}});
        }
        sweeps.push_back({{"lattice", c.lattice}, {"kernel", c.kernel}, {"parameter", c.parameter},
                          {"volume_coefficient", c.ap_name}, {"a_p", c.a_p}, {"k", c.ks}, {"values", c.values},
                          {"eps_rho", c.rho}, {"eps_gradp", c.gradp}, {"solutions", solutions}, {"note", c.design.note}});
    }
    w.print("\n ],\n \"comparison\": {},\n \"surface\": {},\n \"sweeps\": {}\n}}\n", comparison.dump(1),
            surface.dump(1), sweeps.dump(1));
}

} // namespace sphkern
