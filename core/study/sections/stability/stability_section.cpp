#include "study/sections/stability/stability_section.hpp"

#include "codes/code_table.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/h_model.hpp"
#include "stability/stability_budget.hpp"
#include "stability/stability_scan.hpp"
#include "study/declared_keys.hpp"
#include "study/study.hpp"
#include "study/study_inputs.hpp"
#include "study/study_results.hpp"
#include "support/error.hpp"
#include "support/io/json_input.hpp"
#include "support/process/parallel_for.hpp"
#include "support/process/progress.hpp"
#include "support/process/work_budget.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

namespace sphkern {

namespace {

// wave vectors over all k samples (as max_stability_points), kernels x lattices
constexpr double max_stability_points = 1e8;

struct StabilitySpec {
    double gamma = 5.0 / 3.0;
    std::optional<double> k_min, k_max; // empty: the study's window in k, over its volume coefficients
    int steps = 100;                    // k samples - 1
    int grid = 0;                       // first zone grid per reciprocal axis; 0: 8 in 3D, 32 in 2D
    std::optional<double> path_k;       // the dispersion curves' k; empty: the best k of condition (22)
    int path_points = 120;
    double horizon = 100;           // growth time in d/c: slower instabilities are weak (default_horizon)
    HModel h_model = HModel::fixed; // fixed or adaptive h
};

// The bulk cases of the first automatic mode, one per a_p: their windows and condition (22).
std::vector<const StudyCase*> accurate_cases(const Study& study, const StudyResults& results, std::size_t l,
                                             std::size_t k)
{
    std::vector<const StudyCase*> accurate;
    if (const auto mode = first_automatic_mode(study))
        for (std::size_t a = 0; a < study.volume_coefficients.size(); ++a)
            if (const auto* c = find_case(results, {l, k, a, *mode})) accurate.push_back(c);
    return accurate;
}

// The k scanned: the section's, or the union of the study's windows over its volume coefficients.
std::pair<double, double> scanned_k(const StabilitySpec& spec, const StudyInputs& inputs, std::size_t l, std::size_t k)
{
    if (spec.k_min) return {*spec.k_min, *spec.k_max};
    double k_min = INFINITY, k_max = -INFINITY;
    for (double a_p : inputs.a_p[l]) {
        const auto [from, to] = inputs.window(l, k, 0, a_p);
        k_min = std::min(k_min, from);
        k_max = std::max(k_max, to);
    }
    return {k_min, k_max};
}

// Where the accurate k of a bulk case are stable too, and the k recommended there.
StabilityOverlap overlap(const StudyCase& b, const StabilityCase& c, const Kernel& kernel, const Lattice& lattice,
                         double k_max)
{
    StabilityOverlap o{
        b.ap_name, b.acceptance.intervals, accurate_and_stable(b.acceptance.intervals, c.over_k), {}, {}};
    const HydrostaticErrors errors(kernel, lattice, b.sites.empty() ? 0 : b.sites.front(), b.a_p, lattice.gravity,
                                   std::max(k_max, b.k_max));
    o.recommended = recommend_k(o.both, b.k_min, b.k_max, errors);
    if (o.recommended.found)
        for (const CodeProfile* code : study_codes())
            o.in_codes.push_back(code_ships(*code, kernel, lattice.dimension)
                                     ? code_parameter(*code, kernel, lattice.dimension, b.a_p, o.recommended.k,
                                                      errors.at(o.recommended.k).eps_rho)
                                     : NAN);
    return o;
}

StabilityCase stability_case(const StabilitySpec& spec, const Study& study, const StudyInputs& inputs,
                             const StudyResults& results, std::size_t l, std::size_t k)
{
    const Lattice& lattice = inputs.lattices[l];
    const Kernel& kernel = inputs.kernels[k];
    StabilityCase c;
    c.lattice = lattice.name;
    c.kernel_label = kernel.label();
    c.gamma = spec.gamma;
    c.h_model = h_model_name(spec.h_model);
    c.over_k.horizon = spec.horizon; // also for a lattice that is refused
    const auto accurate = accurate_cases(study, results, l, k);
    const auto [k_min, k_max] = scanned_k(spec, inputs, l, k);
    c.path_k = spec.path_k         ? *spec.path_k
               : !accurate.empty() ? accurate.front()->acceptance.best_k
                                   : 0.5 * (k_min + k_max);
    try {
        c.over_k = stability_over_k(kernel, lattice, k_min, k_max, spec.steps, spec.gamma, spec.grid, 1, spec.horizon,
                                    spec.h_model);
        const Dispersion at(kernel, lattice, c.path_k, spec.gamma, spec.h_model);
        c.path = dispersion_along_path(at, reciprocal_lattice(lattice), spec.path_points);
    } catch (const Error& e) {
        if (e.code() != ExitCode::input) throw;
        c.refused = e.what(); // a lattice whose sites are no common equilibrium
    }
    if (!c.refused)
        for (const auto* b : accurate) c.overlap.push_back(overlap(*b, c, kernel, lattice, k_max));
    return c;
}

// Every lattice x kernel case, on every thread.
std::shared_ptr<const SectionResults> run_stability(const StabilitySpec& spec, const Study& study,
                                                    const StudyInputs& inputs, const StudyResults& results)
{
    const std::size_t kernels = inputs.kernels.size();
    std::vector<StabilityCase> cases(inputs.lattices.size() * kernels);
    Progress progress("stability", cases.size(), part_scope(inputs, "stability"));
    std::mutex progress_mutex;
    auto run_case = [&](std::size_t index) {
        cases[index] = stability_case(spec, study, inputs, results, index / kernels, index % kernels);
        std::lock_guard lock(progress_mutex);
        progress.step(inputs.kernels[index % kernels].name() + " on " + inputs.lattices[index / kernels].name);
    };
    // One case per thread at a time, taken in turn: their costs differ by orders of magnitude.
    std::atomic<std::size_t> next{0};
    ParallelFor pool;
    pool.run(cases.size(), worker_threads(0), [&](int, std::size_t, std::size_t) {
        for (std::size_t i; pool.keep_going() && (i = next++) < cases.size();) run_case(i);
    });
    auto out = std::make_shared<StabilityResults>();
    out->cases = std::move(cases);
    return out;
}

class StabilitySection : public StudySection {
public:
    explicit StabilitySection(StabilitySpec spec) : spec_(spec) {}

    void check_budget(const Study& study, const JsonNode& root) const override
    {
        const double points = double(study.kernels.size()) * double(study.lattices.size()) *
                              stability_wave_vectors(spec_.steps, spec_.grid, 0);
        if (points > max_stability_points)
            root.error("the study " + over_budget("kernels x lattices x stability k samples x wave vectors", points,
                                                  max_stability_points));
    }

    SectionRun resolve(const Study& study, KernelRegistry&, StudyInputs& inputs) const override
    {
        if (!spec_.k_min)
            for (std::size_t l = 0; l < inputs.lattices.size(); ++l)
                for (std::size_t k = 0; k < inputs.kernels.size(); ++k)
                    for (double a_p : inputs.a_p[l]) resolve_window(study, inputs, l, k, 0, a_p);
        return [spec = spec_](const Study& study, const StudyInputs& inputs, const StudyResults& bulk) {
            return run_stability(spec, study, inputs, bulk);
        };
    }

private:
    StabilitySpec spec_;
};

} // namespace

std::shared_ptr<const StudySection> read_stability_section(const JsonNode& node, const std::filesystem::path&)
{
    // The section is a front end of `stability`: its settings' keys are the command's rows'.
    node.expect_keys(declared_study_keys("stability", {"gamma", "k", "dispersion_k"}));
    StabilitySpec stability;
    if (auto gamma = node.find("gamma")) stability.gamma = gamma->number_in(1e-6, 1e6);
    if (auto k = node.find("k")) {
        k->expect_keys({"min", "max", "steps"});
        if (k->find("min") || k->find("max")) {
            stability.k_min = k->at("min").number_in(1e-3, 100);
            stability.k_max = k->at("max").number_in(1e-3, 100);
            if (*stability.k_min >= *stability.k_max) k->at("max").error("expected max > min");
        }
    }
    if (auto steps = declared_number(node, "stability", "steps")) stability.steps = static_cast<int>(*steps);
    if (auto grid = declared_number(node, "stability", "grid")) stability.grid = static_cast<int>(*grid);
    if (auto k = node.find("dispersion_k")) stability.path_k = read_k_or_best(*k);
    if (auto points = declared_number(node, "stability", "path")) stability.path_points = static_cast<int>(*points);
    if (auto horizon = declared_node(node, "stability", "horizon")) {
        stability.horizon = horizon->number();
        at_source(ValueSource::json(horizon->file(), horizon->path()),
                  [&] { check_horizon(stability.horizon, "horizon"); });
    }
    if (auto model = declared_node(node, "stability", "h_model")) {
        const std::string name = model->text();
        if (name != "fixed" && name != "adaptive") model->error("expected \"fixed\" or \"adaptive\"");
        stability.h_model = parse_h_model(name, "h_model");
    }
    return std::make_shared<StabilitySection>(stability);
}

} // namespace sphkern
