// The engine's own defaults (what a study or an internal caller gets without the setting)
// against the tables' (what the command line and Python give): one value, or a test fails.
#include "relax/pairing_motion.hpp"
#include "relax/relax_settings.hpp"
#include "requests/settings/command_settings.hpp"
#include "requests/spectrum_request.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace sphkern;

namespace {

double declared(const char* command, const char* key) { return std::stod(settings_of(command)[key].fallback); }

} // namespace

TEST_CASE("relax's engine defaults are the relax table's")
{
    const RelaxSettings s;
    CHECK(s.steps == declared("relax", "steps"));
    CHECK(s.tolerance == declared("relax", "tolerance"));
    CHECK(s.gamma == declared("relax", "gamma"));
    CHECK(s.time_step == declared("relax", "dt"));
    CHECK(s.damping == declared("relax", "damping"));
    CHECK(s.alpha == declared("relax", "alpha"));
    CHECK(s.max_move == declared("relax", "max_move"));
    CHECK(s.threads == declared("relax", "threads"));
    CHECK(settings_of("relax")["method"].fallback == "pressure");
    CHECK(s.method == RelaxMethod::pressure);
}

TEST_CASE("pairing's and spectrum's request defaults are their tables'")
{
    const PairingRequest p;
    CHECK(p.samples == declared("pairing", "samples"));
    CHECK(p.noise == declared("pairing", "noise"));
    CHECK(p.duration == declared("pairing", "duration"));
    CHECK(p.damping == declared("pairing", "damping"));
    CHECK(p.time_step == declared("pairing", "dt"));
    CHECK(p.gamma == declared("pairing", "gamma"));
    CHECK(p.horizon == declared("pairing", "horizon"));
    CHECK(p.seed == declared("pairing", "seed"));
    const SpectrumRequest s;
    CHECK(s.k == declared("spectrum", "k"));
    CHECK(s.kh_max == declared("spectrum", "max"));
    CHECK(s.points == declared("spectrum", "points"));
}
