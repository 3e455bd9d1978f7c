#include "study/sections/sweeps/sweep_section.hpp"

#include "study/study.hpp"
#include "study/study_inputs.hpp"
#include "support/io/file_spec.hpp"
#include "support/io/json_input.hpp"
#include "support/process/interruption.hpp"
#include "support/process/work_budget.hpp"

#include <algorithm>

namespace sphkern {

namespace {

constexpr double max_sweep_points = 2e6; // lattices x sweep samples x k samples, over all sweeps

struct SweepSpec {
    std::string kernel;                       // name, plugin or expression file, or a blend A+B
    std::map<std::string, double> parameters; // other parameter values
    std::string parameter;
    double min = 0, max = 1;
    int samples = 41;
    std::string json_path;
};

// A sweep's kernel and its window on each lattice whose dimension it supports (empty where not).
struct ResolvedSweep {
    SweepSpec spec;
    Kernel kernel;
    std::vector<std::optional<std::pair<double, double>>> windows; // [lattice]
};

// Both errors over the (k, parameter) grid.
void sweep_grid(const SweepSpec& sweep, const Kernel& kernel, const Lattice& lattice, double k_max, SweepCase& c)
{
    for (int i = 0; i < sweep.samples; ++i) {
        throw_if_interrupted();
        double value = sweep.min + (sweep.max - sweep.min) * i / (sweep.samples - 1);
        auto values = sweep.parameters;
        values[sweep.parameter] = value;
        Kernel at(kernel.shared_definition(), values);
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
}

SweepCase sweep_case(const Study& study, const StudyInputs& inputs, const ResolvedSweep& s, std::size_t l)
{
    const SweepSpec& sweep = s.spec;
    const Lattice& lattice = inputs.lattices[l];
    SweepCase c;
    c.lattice = lattice.name;
    c.kernel = s.kernel.name();
    c.parameter = sweep.parameter;
    c.ap_name = study.volume_coefficients[0].name;
    c.a_p = inputs.a_p[l][0];
    // Sweeps keep one k grid per lattice: the window of the sweep's kernel at its declared parameters.
    const auto [k_min, k_max] = *s.windows[l];
    DesignProblem problem{&lattice, 0, c.a_p, lattice.gravity, k_min, k_max, sweep.parameter, sweep.min, sweep.max};
    c.design = at_source(study_source(study, sweep.json_path), [&] { return design_kernel(s.kernel, problem); });
    const int k_samples = std::min(study.samples, 201);
    for (int j = 0; j < k_samples; ++j) c.ks.push_back(k_min + (k_max - k_min) * j / (k_samples - 1));
    sweep_grid(sweep, s.kernel, lattice, k_max, c);
    for (const auto& solution : c.design.solutions) {
        auto values = sweep.parameters;
        values[sweep.parameter] = solution.parameter;
        Kernel designed(s.kernel.shared_definition(), values);
        HydrostaticErrors errors(designed, lattice, 0, c.a_p, lattice.gravity, k_max);
        c.designed_acceptance.push_back(evaluate_acceptance(errors, k_min, k_max, study.epsilon));
    }
    return c;
}

class SweepSection : public StudySection {
public:
    explicit SweepSection(std::vector<SweepSpec> sweeps) : sweeps_(std::move(sweeps)) {}

    void check_budget(const Study& study, const JsonNode& root) const override
    {
        double points = 0;
        for (const auto& s : sweeps_)
            points += double(study.lattices.size()) * s.samples * std::min(study.samples, 201);
        if (points > max_sweep_points)
            root.error("the study " +
                       over_budget("lattices x sweep samples x k samples, over all sweeps", points, max_sweep_points));
    }

    SectionRun resolve(const Study& study, KernelRegistry& registry, StudyInputs& inputs) const override
    {
        std::vector<ResolvedSweep> resolved;
        for (const auto& sweep : sweeps_) {
            Kernel kernel = at_source(study_source(study, sweep.json_path), [&] {
                Kernel k(registry.find(sweep.kernel), sweep.parameters);
                check_design_parameter(k, sweep.parameter, sweep.min, sweep.max);
                return k;
            });
            std::vector<std::optional<std::pair<double, double>>> windows;
            for (std::size_t l = 0; l < inputs.lattices.size(); ++l)
                windows.push_back(
                    kernel.supports(inputs.lattices[l].dimension)
                        ? std::optional(study_window(study, kernel, inputs.lattices[l], 0, inputs.a_p[l].front()))
                        : std::nullopt);
            resolved.push_back({sweep, std::move(kernel), std::move(windows)});
        }
        return [resolved](const Study& study, const StudyInputs& inputs, const StudyResults&) {
            auto results = std::make_shared<SweepResults>();
            for (const auto& s : resolved)
                for (std::size_t l = 0; l < inputs.lattices.size(); ++l) {
                    if (!s.windows[l]) continue;
                    results->cases.push_back(sweep_case(study, inputs, s, l));
                    throw_if_interrupted();
                }
            return std::shared_ptr<const SectionResults>(results);
        };
    }

private:
    std::vector<SweepSpec> sweeps_;
};

SweepSpec read_sweep(const JsonNode& node, const std::filesystem::path& file)
{
    node.expect_keys({"kernel", "set", "parameter", "range", "samples"});
    SweepSpec sweep;
    sweep.json_path = node.path();
    sweep.kernel = resolve_beside(node.at("kernel").string(), file, kernel_file_extensions);
    if (auto set = node.find("set")) sweep.parameters = read_parameter_values(*set);
    sweep.parameter = node.at("parameter").string();
    auto range = node.at("range");
    range.expect_array(2, 2);
    sweep.min = range[0].number();
    sweep.max = range[1].number();
    if (!(sweep.min < sweep.max)) range.error("expected [min, max] with min < max");
    if (auto n = node.find("samples")) sweep.samples = static_cast<int>(n->integer_in(3, 1000));
    return sweep;
}

} // namespace

std::shared_ptr<const StudySection> read_sweep_section(const JsonNode& node, const std::filesystem::path& study_file)
{
    node.expect_array(1, 20);
    std::vector<SweepSpec> sweeps;
    for (std::size_t i = 0; i < node.size(); ++i) sweeps.push_back(read_sweep(node[i], study_file));
    return std::make_shared<SweepSection>(std::move(sweeps));
}

} // namespace sphkern
