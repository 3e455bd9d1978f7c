#include "requests/assess_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "analysis/resolution_axis.hpp"
#include "requests/code_setting.hpp"
#include "stability/brillouin_zone.hpp"
#include "stability/dispersion.hpp"
#include "stability/stability_over_k.hpp"
#include "support/error.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace sphkern {

namespace {

RootsRequest window_request(const AssessRequest& r, const CodeProfile* code, double gamma)
{
    RootsRequest w;
    w.window_min = r.window_min;
    w.window_max = r.window_max;
    w.epsilon = r.epsilon;
    w.stability = true;
    // The code's own h model: SWIFT, Phantom and GADGET set h from each particle's density.
    w.model = {gamma, r.horizon, 100, code && code->from_sph_density ? HModel::adaptive : HModel::fixed, r.threads};
    w.code = code;
    w.evaluation = r.setting.evaluation;
    return w;
}

RootsSources window_sources(const AssessSources& s)
{
    return {s.window, s.epsilon, s.gamma, s.horizon, ValueSource::argument("steps"), s.setting.evaluation};
}

// "SWIFT eta 1.2348" or "k = 1.2".
std::string setting_text(const AssessResult& a)
{
    if (a.at.code)
        return fmt::format("{} {} {:g}", a.at.code->setting.code, a.at.code->parameter, a.at.code->setting.value);
    return fmt::format("k = {:g}", a.at.k);
}

// The verdict of the h model the code runs: SWIFT, Phantom and GADGET set h from the density.
const AssessStability& own_model(const AssessResult& a)
{
    const bool adaptive = a.code && a.code->from_sph_density;
    return a.stability[adaptive ? 1 : 0];
}

} // namespace

std::string stability_text(const AssessStability& s)
{
    if (s.verdict == Verdict::stable) return "stable";
    return fmt::format("{} ({} mode growing in {:.3g} d/c)",
                       s.verdict == Verdict::weak ? "weakly unstable" : "unstable", s.mode, s.growth_time);
}

namespace {

std::string accuracy_text(const AssessResult& a, double epsilon)
{
    const auto& v = a.at.sites[a.at.worst].values;
    const bool rho = std::abs(v.eps_rho) >= std::abs(v.eps_gradp);
    const double worst = rho ? std::abs(v.eps_rho) : std::abs(v.eps_gradp);
    return fmt::format("{} (|{}| {:.3g} {} {:g})", a.accurate(epsilon) ? "accurate" : "inaccurate",
                       rho ? "eps_rho" : "eps_gradP", worst, a.accurate(epsilon) ? "<=" : ">", epsilon);
}

// "eta 1.25 to 1.31" or "k 1.02 to 1.07".
std::string window_text(const AssessResult& a, const AssessWindow& w)
{
    if (w.code) return fmt::format("{} {:.3g} to {:.3g}", a.code->parameter, w.code->from, w.code->to);
    return fmt::format("k {:.3g} to {:.3g}", w.k.from, w.k.to);
}

// "; narrow: +-0.81% in h, less than the +-2% a relaxed glass's h spans", where it is.
std::string narrow_text(double relative_half_width)
{
    if (relative_half_width >= robust_half_width) return "";
    return fmt::format("; narrow: +-{:.2g}% in h, less than the +-{:g}% a relaxed glass's h spans",
                       100 * relative_half_width, 100 * robust_half_width);
}

std::string recommendation_text(const AssessResult& a, const AssessRequest& r)
{
    const auto& rec = a.window.stability.recommended;
    if (!rec.found)
        return fmt::format("no setting of k in [{:g}, {:g}] is both accurate and stable", r.window_min, r.window_max);
    const std::string edge = rec.at_window_edge ? ", at the window's edge: widen it" : "";
    const std::string nh = fmt::format(", N_H {} to {}", rec.neighbours_from, rec.neighbours_to);
    const std::string narrow = narrow_text(rec.margin / rec.k);
    std::string text;
    if (const auto& c = a.window.in_code; c && c->recommended)
        text = fmt::format("recommended {} {:.3g} ({:.3g} to {:.3g}{}{}{})", a.code->parameter, c->recommended_value,
                           c->recommended->from, c->recommended->to, nh, edge, narrow);
    else
        text = fmt::format("recommended k {:.3g} ({:.3g} to {:.3g}{}{}{})", rec.k, rec.widest.from, rec.widest.to, nh,
                           edge, narrow);
    // The window of the setting given, or the nearest to it, where it is another.
    if (a.nearest &&
        !(a.windows[*a.nearest].k.from == rec.widest.from && a.windows[*a.nearest].k.to == rec.widest.to)) {
        const auto& w = a.windows[*a.nearest];
        const bool holds = a.at.k >= w.k.from && a.at.k <= w.k.to;
        text += fmt::format("; {} the setting: {}{}", holds ? "the window holding" : "nearest to", window_text(a, w),
                            narrow_text(w.relative_half_width));
    }
    if (a.windows.size() > 1) text += fmt::format(" ({} windows in all)", a.windows.size());
    return text;
}

// Every interval both accurate and stable, and the one holding or nearest to the setting's k.
void find_windows(AssessResult& a)
{
    const auto& both = a.window.stability.both;
    double nearest = INFINITY;
    for (std::size_t i = 0; i < both.size(); ++i) {
        AssessWindow w{both[i], std::nullopt, (both[i].to - both[i].from) / (both[i].to + both[i].from)};
        if (a.window.in_code && i < a.window.in_code->both.size()) w.code = a.window.in_code->both[i];
        const double distance = std::max({0.0, w.k.from - a.at.k, a.at.k - w.k.to});
        if (distance < nearest) nearest = distance, a.nearest = i;
        a.windows.push_back(w);
    }
}

// The glass at the recommended setting: its h over l from the recommended k at the lattice's
// a_p, relaxed under the user's gamma, measured with the code's own h where the code solves h
// from the density; the lattice's errors at that k beside it.
GlassAtSetting glass_of(const AssessRequest& r, const AssessSources& sources, const AssessResult& a,
                        const Kernel& kernel, const Lattice& lattice)
{
    const double k = a.window.stability.recommended.k;
    const double h_over_l = eta_of_k(k, a.at.a_p, lattice.dimension);
    SmoothingSpec measure{SmoothingRule::eta, h_over_l, 0};
    if (const auto& c = a.window.in_code; a.code && a.code->from_sph_density && c && c->recommended)
        measure = code_smoothing({r.setting.code->code, c->recommended_value},
                                 {sources.setting.code, sources.setting.code_value}, kernel, lattice.dimension);
    GlassAtSetting glass = glass_at(kernel, lattice.dimension, h_over_l, measure, r.glass, r.gamma, r.threads);
    EpsRequest at_k = r.setting;
    at_k.code.reset(), at_k.k = {k}, at_k.axis = Axis::k;
    const ErrorValues lattice_errors = run_eps_at_k(at_k, sources.setting, kernel, lattice).chosen();
    glass.lattice_eps_rho = lattice_errors.eps_rho, glass.lattice_eps_gradp = lattice_errors.eps_gradp;
    return glass;
}

void print_glass(const GlassAtSetting& g)
{
    const std::string how =
        g.settled ? fmt::format("settled after {} steps", g.steps) : fmt::format("not settled in {} steps", g.steps);
    fmt::print(results_file(),
               "on a relaxed glass ({} particles, h over l {:.4g}, {}): e0 p1 {:.3g}, p50 {:.3g}, p99 {:.3g} (RMS "
               "{:.3g}; the Poisson start's {:.3g}), eps_gradp p1 {:.3g}, p50 {:.3g}, p99 {:.3g} (RMS {:.3g}); the "
               "lattice's eps_rho {:.3g}, eps_gradP {:.3g}\n",
               g.particles, g.h_over_l, how, g.e0.p1, g.e0.p50, g.e0.p99, g.e0.rms, g.poisson_rms_e0, g.eps_gradp.p1,
               g.eps_gradp.p50, g.eps_gradp.p99, g.eps_gradp.rms, g.lattice_eps_rho, g.lattice_eps_gradp);
}

} // namespace

AssessStability stability_at(const Kernel& kernel, const Lattice& lattice, double k, double gamma, HModel h,
                             double horizon)
{
    const auto sample =
        stability_sample(Dispersion(kernel, lattice, k, gamma, h), reciprocal_lattice(lattice), 0, 0, horizon);
    AssessStability s{h, sample.verdict, sample.growth_time, ""};
    if (sample.verdict != Verdict::stable) s.mode = mode_kind_name(sample.mode.kind);
    return s;
}

void check_epsilon(double epsilon, const ValueSource& source)
{
    if (!std::isfinite(epsilon) || epsilon <= 0 || epsilon >= 1)
        source.fail(fmt::format("{}: expected a number in (0, 1)", epsilon));
}

void check_assess_request(const AssessRequest& r, const AssessSources& sources)
{
    check_eps_request(r.setting, sources.setting);
    check_k_interval(r.window_min, r.window_max, sources.window);
    check_epsilon(r.epsilon, sources.epsilon);
    check_gamma(r.gamma, sources.gamma.name);
    check_horizon(r.horizon, sources.horizon.name);
    if (r.glass != 0 && (r.glass < 100 || r.glass > 100000))
        sources.glass.fail(fmt::format("{} particles; expected 100 to 100000 (0: no glass)", r.glass));
    check_setting(settings_of("assess")["threads"], r.threads, sources.threads);
}

AssessResult run_assess(const AssessRequest& r, const AssessSources& sources, const Kernel& kernel,
                        const Lattice& lattice)
{
    AssessResult a;
    if (r.setting.code) a.code = &code_profile(r.setting.code->code, sources.setting.code);
    if (a.code) require_lattice_volume(*a.code, "the window of the recommended setting (at the lattice's a_p)");
    a.at = run_eps_at_k(r.setting, sources.setting, kernel, lattice);
    for (const auto& s : a.at.sites)
        a.worst = std::max({a.worst, std::abs(s.values.eps_rho), std::abs(s.values.eps_gradp)});
    a.pressure = stability_pressure(a.code, r.gamma, r.coef_sound, sources.coef_sound);
    for (const HModel h : {HModel::fixed, HModel::adaptive})
        a.stability.push_back(stability_at(kernel, lattice, a.at.k, a.pressure.gamma, h, r.horizon));
    a.window = run_roots(window_request(r, a.code, a.pressure.gamma), window_sources(sources), kernel, lattice);
    find_windows(a);
    if (r.glass > 0 && a.window.stability.recommended.found) a.glass = glass_of(r, sources, a, kernel, lattice);
    a.verdict = fmt::format("{} with {} on {}: {}, {}; {}", setting_text(a), a.at.kernel, a.at.lattice,
                            stability_text(own_model(a)), accuracy_text(a, r.epsilon), recommendation_text(a, r));
    return a;
}

namespace {

nlohmann::json glass_json(const GlassAtSetting& g)
{
    auto summary = [](const Summary& s) {
        return nlohmann::json{{"rms", s.rms}, {"p1", s.p1}, {"p50", s.p50}, {"p99", s.p99}};
    };
    return {{"particles", g.particles},
            {"h_over_l", g.h_over_l},
            {"steps", g.steps},
            {"settled", g.settled},
            {"settle_steps", glass_settle_steps},
            {"e0", summary(g.e0)},
            {"eps_gradp", summary(g.eps_gradp)},
            {"poisson_rms_e0", g.poisson_rms_e0},
            {"lattice", {{"eps_rho", g.lattice_eps_rho}, {"eps_gradp", g.lattice_eps_gradp}}}};
}

} // namespace

nlohmann::json assess_document(const AssessRequest& r, const AssessResult& a)
{
    nlohmann::json stability = nlohmann::json::array();
    for (const auto& s : a.stability) {
        nlohmann::json one = {{"h_model", h_model_name(s.h_model)}, {"verdict", verdict_name(s.verdict)}};
        if (s.verdict != Verdict::stable) one.update({{"growth_time", s.growth_time}, {"mode", s.mode}});
        stability.push_back(one);
    }
    const auto& rec = a.window.stability.recommended;
    nlohmann::json recommended = {{"found", rec.found}};
    if (rec.found)
        recommended.update({{"k", rec.k},
                            {"interval", {rec.widest.from, rec.widest.to}},
                            {"nh", {rec.neighbours_from, rec.neighbours_to}},
                            {"relative_half_width", rec.margin / rec.k},
                            {"robust", rec.margin / rec.k >= robust_half_width}});
    nlohmann::json windows = nlohmann::json::array();
    for (const auto& w : a.windows) {
        nlohmann::json one = {{"k", {w.k.from, w.k.to}},
                              {"relative_half_width", w.relative_half_width},
                              {"robust", w.robust()}};
        if (w.code) one["code"] = {w.code->from, w.code->to};
        windows.push_back(one);
    }
    if (const auto& c = a.window.in_code; c && c->recommended)
        recommended["code"] = {{"parameter", a.code->parameter},
                               {"value", c->recommended_value},
                               {"interval", {c->recommended->from, c->recommended->to}}};
    return {{"eps", eps_document(a.at)},
            {"condition_22",
             {{"epsilon", r.epsilon}, {"holds", a.accurate(r.epsilon)}, {"margin", r.epsilon - a.worst}}},
            {"stability", stability},
            {"pressure",
             a.pressure.tait
                 ? nlohmann::json{{"model", "tait"},
                                  {"coef_sound", a.pressure.coef_sound},
                                  {"p0_over_rho_c2", 1 / a.pressure.gamma},
                                  {"text", a.pressure.text}}
                 : nlohmann::json{{"model", "ideal_gas"}, {"gamma", a.pressure.gamma}, {"text", a.pressure.text}}},
            {"window", {r.window_min, r.window_max}},
            {"recommended", recommended},
            {"windows", windows},
            {"nearest_window", a.nearest ? nlohmann::json(*a.nearest) : nlohmann::json()},
            {"robust_half_width", robust_half_width},
            {"glass", a.glass ? glass_json(*a.glass) : nlohmann::json()},
            {"verdict", a.verdict}};
}

void print_assess(const AssessRequest& r, const AssessResult& a)
{
    print_eps(a.at);
    fmt::print(results_file(),
               "condition (22), epsilon = {:g}: {} (margin {:.3g}: epsilon less the largest error at any site)\n",
               r.epsilon, a.accurate(r.epsilon) ? "holds at every site" : "fails", r.epsilon - a.worst);
    const std::string pressure = a.pressure.tait ? a.pressure.text : fmt::format("gamma = {:g}", r.gamma);
    for (const auto& s : a.stability)
        fmt::print(results_file(), "linear stability, {} h ({}): {}\n", h_model_name(s.h_model), pressure,
                   stability_text(s));
    fmt::print(results_file(), "{}\n", a.verdict);
    if (a.glass) print_glass(*a.glass);
    else if (r.glass > 0) fmt::print(results_file(), "no glass relaxed: the window recommends no setting\n");
}

} // namespace sphkern
