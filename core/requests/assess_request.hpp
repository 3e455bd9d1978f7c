// One verdict on a setting (`sphkern assess`, Python's sphkern.assess): a k, or an SPH code's
// own setting, on a lattice: the errors at every site against condition (22) with the
// margin, the linear verdict for fixed and adaptive h (with the growth time and the kind of
// the fastest mode where unstable), the recommended setting of a window, and one line a
// person can act on.
#pragma once

#include "requests/assess_glass.hpp"
#include "requests/eps_request.hpp"
#include "requests/roots_request.hpp"
#include "stability/h_model.hpp"
#include "stability/stability_scan.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sphkern {

struct AssessRequest {
    EpsRequest setting;                         // one k, or the code's setting
    double window_min = 0.75, window_max = 2.0; // in k: where a setting is recommended
    double epsilon = 0.01;                      // of condition (22)
    double gamma = 5.0 / 3.0, horizon = default_horizon;
    std::optional<double> coef_sound; // a Tait code's c / sqrt(g H), default the code's
    int threads = 0;                  // of the window's scan over k (0: every core)
    std::size_t glass = 0;            // particles of a glass relaxed and measured at the recommended setting (0: none)
};

struct AssessSources {
    EpsSources setting;
    ValueSource window, epsilon, gamma, horizon;
    ValueSource coef_sound = ValueSource::argument("coef_sound");
    ValueSource glass = ValueSource::argument("glass");
    ValueSource threads = ValueSource::argument("threads");
};

struct AssessStability {
    HModel h_model = HModel::fixed;
    Verdict verdict = Verdict::stable;
    double growth_time = 0; // d/c, where a mode grows
    std::string mode;       // its kind ("longitudinal", "transverse", "optical"), where one grows
};

// The linear verdict at one k for an h model (the fastest mode's kind and growth time where
// unstable), and it in words: "stable", "unstable (transverse mode growing in 9.75 d/c)".
AssessStability stability_at(const Kernel& kernel, const Lattice& lattice, double k, double gamma, HModel h,
                             double horizon);
std::string stability_text(const AssessStability& s);

// A window narrower than this, half its width over its centre in h, is no setting for real
// particles: a relaxed glass's own h spans about +-2% (p1 to p99 of SWIFT's solve on a glass
// that `relax` makes; a test measures it). Such a window is flagged, not recommended silently.
inline constexpr double robust_half_width = 0.02;

// One interval of k where the setting is both accurate and stable, and it in the code's setting.
struct AssessWindow {
    KInterval k{0, 0};
    std::optional<KInterval> code;
    double relative_half_width = 0; // in h: (to - from) / (to + from)
    bool robust() const { return relative_half_width >= robust_half_width; }
};

struct AssessResult {
    EpsAtK at;                              // k and the errors at every site
    double worst = 0;                       // the largest |eps_rho| or |eps_gradP| over the sites
    std::vector<AssessStability> stability; // fixed h, then adaptive h
    RootsResult window;                     // condition (22), stability and the recommended k of the window
    std::vector<AssessWindow> windows;      // every interval both accurate and stable, in k order
    std::optional<std::size_t> nearest;     // the window that holds the setting, or the nearest to it
    const CodeProfile* code = nullptr;
    StabilityPressure pressure;          // the pressure at rest the verdicts assume
    std::optional<GlassAtSetting> glass; // with a glass asked for and a setting recommended
    std::string verdict;                 // the one line
    bool accurate(double epsilon) const { return worst <= epsilon; }
};

void check_assess_request(const AssessRequest& request, const AssessSources& sources);
// Condition (22)'s tolerance: in (0, 1).
void check_epsilon(double epsilon, const ValueSource& source);
AssessResult run_assess(const AssessRequest& request, const AssessSources& sources, const Kernel& kernel,
                        const Lattice& lattice);
nlohmann::json assess_document(const AssessRequest& request, const AssessResult& result);
void print_assess(const AssessRequest& request, const AssessResult& result);

} // namespace sphkern
