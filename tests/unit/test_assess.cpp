// One verdict on a setting: its accuracy from the lattice sums at every site, its stability
// from the stable intervals over k (the cover, a path of its own), its recommendation inside
// the window's, on three settings whose answers are known.
#include "analysis/site_errors.hpp"
#include "helpers.hpp"
#include "requests/assess_request.hpp"
#include "stability/stability_over_k.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace sphkern;
using namespace sphkern::test;

namespace {

AssessSources sources()
{
    return {{ValueSource::option("--k"),
             ValueSource::option("--axis"),
             {ValueSource::option("--gravity"), ValueSource::option("--site"), ValueSource::option("--shells")},
             ValueSource::option("--code"),
             ValueSource::option("--value")},
            ValueSource::option("--kmin/--kmax"),
            ValueSource::option("--epsilon"),
            ValueSource::option("--gamma"),
            ValueSource::option("--horizon")};
}

bool inside(const std::vector<KInterval>& intervals, double k)
{
    return std::any_of(intervals.begin(), intervals.end(),
                       [&](const KInterval& i) { return i.from <= k && k <= i.to; });
}

} // namespace

TEST_CASE(
    "assess: accuracy from every site's sums, stability from the intervals over k, the recommendation in the window")
{
    const auto lattice = load_lattice("fcc");
    struct Case {
        const char* kernel;
        std::optional<CodeSetting> code;
        double k;
        bool accurate, stable;
        const char* line;
    };
    const Case cases[] = {{"wendland_c2", CodeSetting{"swift", 1.2348}, 0, false, true,
                           "swift eta 1.2348 with wendland_c2 on fcc: stable, inaccurate (|eps_gradP| 0.0205 > 0.01); "
                           "recommended eta 1.7 (1.68 to 1.71, N_H 140 to 140; narrow: +-0.81% in h"},
                          {"wendland_c2", CodeSetting{"swift", 1.7}, 0, true, true,
                           "swift eta 1.7 with wendland_c2 on fcc: stable, accurate"},
                          {"cubic_bspline", std::nullopt, 1.6, true, false,
                           "k = 1.6 with cubic_bspline on fcc: unstable (transverse mode growing in"}};
    for (const auto& c : cases) {
        CAPTURE(c.kernel);
        const auto kernel = shipped_kernel(c.kernel);
        AssessRequest request;
        request.setting.code = c.code;
        if (!c.code) request.setting.k = {c.k};
        check_assess_request(request, sources());
        const auto a = run_assess(request, sources(), kernel, lattice);
        // Accuracy: the largest error over the sites, summed anew.
        const double a_p = lattice.volume_coefficient("voronoi");
        double worst = 0;
        for (const auto& s : errors_per_site(kernel, lattice, every_site(lattice), a_p, lattice.gravity, a.at.k)) {
            const auto v = s->at(a.at.k);
            worst = std::max({worst, std::abs(v.eps_rho), std::abs(v.eps_gradp)});
        }
        CHECK(worst == doctest::Approx(a.worst).epsilon(1e-12));
        CHECK(a.accurate(0.01) == c.accurate);
        CHECK((worst <= 0.01) == c.accurate);
        // Stability (fixed h): the verdict at k against the stable intervals of a window around it.
        const auto over = stability_over_k(kernel, lattice, a.at.k - 0.05, a.at.k + 0.05, 4, 5.0 / 3.0, 0, 2);
        CHECK(inside(over.usable, a.at.k) == c.stable);
        CHECK((a.stability[0].verdict != Verdict::unstable) == c.stable);
        // The recommended k lies in the window's intervals of condition (22) and of stability.
        const auto& rec = a.window.stability.recommended;
        REQUIRE(rec.found);
        CHECK(inside(a.window.analysis.all_along.intervals, rec.k));
        CHECK(inside(a.window.stability.stable, rec.k));
        CHECK(a.verdict.rfind(c.line, 0) == 0);
    }
}
