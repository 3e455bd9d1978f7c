#include "study/sections/surface/surface_section.hpp"

#include "study/study.hpp"
#include "study/study_error.hpp"
#include "study/study_inputs.hpp"
#include "support/io/json_input.hpp"
#include "support/process/interruption.hpp"
#include "support/process/work_budget.hpp"

namespace sphkern {

namespace {

constexpr double max_surface_layers = 1e6; // kernels x lattices x forms x layers

struct SurfaceSpec {
    std::optional<double> k; // empty: each kernel's best k (condition 22, first mode)
    int layers = 6;
    std::vector<GradientForm> forms = {GradientForm::sum};
    std::optional<StudyVolumeCoefficient> volume_coefficient; // empty: the study's first
};

// The profiles, at each lattice's a_p (`a_p`, resolved).
std::shared_ptr<const SectionResults> run_surface(const SurfaceSpec& spec, const std::vector<double>& a_p_of,
                                                  const Study& study, const StudyInputs& inputs)
{
    auto results = std::make_shared<SurfaceResults>();
    const std::string ap_name =
        spec.volume_coefficient ? spec.volume_coefficient->name : study.volume_coefficients[0].name;
    for (std::size_t l = 0; l < inputs.lattices.size(); ++l) {
        const Lattice& lattice = inputs.lattices[l];
        const double a_p = a_p_of[l];
        for (std::size_t i = 0; i < inputs.kernels.size(); ++i) {
            const Kernel& kernel = inputs.kernels[i];
            double k = 0;
            if (spec.k) {
                k = *spec.k;
            } else { // the best k of condition (22) in the first mode, for this a_p, in the study's window
                const auto [k_min, k_max] = inputs.window(l, i, 0, a_p);
                HydrostaticErrors errors(kernel, lattice, 0, a_p, lattice.gravity, k_max, inputs.evaluation[0][i]);
                k = evaluate_acceptance(errors, k_min, k_max, study.epsilon).best_k;
            }
            for (const auto form : spec.forms) {
                SurfaceCase c{lattice.name, kernel.label(), gradient_form_name(form), ap_name, a_p, k, {}};
                c.profile = at_source(study_source(study, "/surface"), [&] {
                    return surface_profile(kernel, lattice, 0, a_p, lattice.gravity, k, spec.layers, form);
                });
                results->cases.push_back(std::move(c));
                throw_if_interrupted();
            }
        }
    }
    return results;
}

class SurfaceSection : public StudySection {
public:
    explicit SurfaceSection(SurfaceSpec spec) : spec_(std::move(spec)) {}

    void check_budget(const Study& study, const JsonNode& root) const override
    {
        const double layers =
            double(study.kernels.size()) * double(study.lattices.size()) * double(spec_.forms.size()) * spec_.layers;
        if (layers > max_surface_layers)
            root.error("the study " +
                       over_budget("kernels x lattices x surface forms x layers", layers, max_surface_layers));
    }

    SectionRun resolve(const Study& study, KernelRegistry&, StudyInputs& inputs) const override
    {
        std::vector<double> a_p;
        for (std::size_t l = 0; l < inputs.lattices.size(); ++l) {
            a_p.push_back(spec_.volume_coefficient
                              ? at_source(study_source(study, "/surface/volume_coefficient"),
                                          [&] { return spec_.volume_coefficient->on(inputs.lattices[l]); })
                              : inputs.a_p[l].front());
            if (!spec_.k)
                for (std::size_t k = 0; k < inputs.kernels.size(); ++k)
                    resolve_window(study, inputs, l, k, 0, a_p.back());
        }
        return [spec = spec_, a_p](const Study& study, const StudyInputs& inputs, const StudyResults&) {
            return run_surface(spec, a_p, study, inputs);
        };
    }

private:
    SurfaceSpec spec_;
};

} // namespace

std::shared_ptr<const StudySection> read_surface_section(const JsonNode& node, const std::filesystem::path&)
{
    node.expect_keys({"k", "layers", "forms", "volume_coefficient"});
    SurfaceSpec spec;
    if (auto k = node.find("k")) spec.k = read_k_or_best(*k);
    if (auto layers = node.find("layers")) spec.layers = static_cast<int>(layers->integer_in(1, 1000));
    if (auto forms = node.find("forms")) {
        const auto names = read_string_list(*forms);
        spec.forms.clear();
        for (std::size_t i = 0; i < names.size(); ++i) {
            const auto item = (*forms)[i];
            spec.forms.push_back(
                at_study_path(item.file(), item.path(), [&] { return parse_gradient_form(names[i]); }));
        }
    }
    if (auto ap = node.find("volume_coefficient")) spec.volume_coefficient = read_volume_coefficient(*ap);
    return std::make_shared<SurfaceSection>(std::move(spec));
}

} // namespace sphkern
