// The one set of input validators: each refusal names its source and keeps its exit code.
#include "helpers.hpp"
#include "support/text/setting_names.hpp"
#include "support/text/value_checks.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

using namespace sphkern;
using test::refusal;

TEST_CASE("value checks: k from 0 (excluded) to 100 named by option or argument")
{
    CHECK(k_in_range(100));
    CHECK(k_in_range(std::nextafter(0.0, 1.0)));
    CHECK_FALSE(k_in_range(0));
    CHECK_FALSE(k_in_range(std::nextafter(100.0, 200.0)));
    CHECK_FALSE(k_in_range(std::numeric_limits<double>::quiet_NaN()));
    CHECK_FALSE(k_in_range(std::numeric_limits<double>::infinity()));
    auto option = refusal([] { check_k(-1, ValueSource::option("--k")); });
    CHECK(option.first == "--k -1 is not allowed, expected a number in (0, 100]");
    CHECK(option.second == ExitCode::usage);
    auto argument = refusal([] { check_k(200, ValueSource::argument("k"), "; hint"); });
    CHECK(argument.first == "k = 200 is not allowed, expected a number in (0, 100]; hint");
    CHECK(argument.second == ExitCode::input);
}

TEST_CASE("value checks: k intervals as one named value or two options")
{
    CHECK(refusal([] { check_k_interval(1, 2, ValueSource::argument("k")); }).second == ExitCode::ok);
    CHECK(refusal([] { check_k_interval(1, 1, ValueSource::argument("k"), IntervalEnds::may_meet); }).second ==
          ExitCode::ok);
    CHECK(refusal([] { check_k_interval(1, 1, ValueSource::argument("k interval")); }).first ==
          "k interval: [1, 1] is not allowed, expected 0 < min < max <= 100");
    CHECK(refusal([] { check_k_interval(0, 1, ValueSource::json("s.json", "/k")); }).first ==
          "s.json: /k: [0, 1] is not allowed, expected 0 < min < max <= 100");
    auto pair = refusal([] {
        check_k_interval(2, 1, ValueSource::option("--kmin"), ValueSource::option("--kmax"), IntervalEnds::may_meet);
    });
    CHECK(pair.first == "--kmin 2 --kmax 1: expected 0 < kmin <= kmax <= 100");
    CHECK(pair.second == ExitCode::usage);
    CHECK(refusal([] {
              check_k_interval(1, 101, ValueSource::option("--kmin"), ValueSource::option("--kmax"));
          }).first == "--kmin 1 --kmax 101: expected 0 < kmin < kmax <= 100");
    CHECK(refusal([] { check_k_interval(0, 1, ValueSource::argument("kmin"), ValueSource::argument("kmax")); }).first ==
          "kmin = 0, kmax = 1: expected 0 < kmin < kmax <= 100");
}

TEST_CASE("value checks: identifiers and suggestions")
{
    CHECK(is_identifier("cubic_bspline2"));
    CHECK_FALSE(is_identifier(""));
    CHECK_FALSE(is_identifier("Cubic"));
    CHECK_FALSE(is_identifier("fcc-2"));
    CHECK(is_identifier("fcc-2", "-"));
    CHECK(is_identifier(std::string(64, 'a')));
    CHECK_FALSE(is_identifier(std::string(65, 'a')));
    CHECK(did_you_mean("cubic", {"cubic_bspline", "quintic"}) == "");
    CHECK(did_you_mean("wendlnd_c2", {"cubic_bspline", "wendland_c2"}) == " (did you mean \"wendland_c2\"?)");
}

TEST_CASE("value checks: comma-separated numbers")
{
    CHECK(parse_number_list("1,-2.5,3e2", ValueSource::option("--box")) == std::vector<double>{1, -2.5, 300});
    auto bad = refusal([] { parse_number_list("1,nan", ValueSource::option("--wavevector")); });
    CHECK(bad.first == "--wavevector 1,nan: \"nan\" is not a finite number");
    CHECK(bad.second == ExitCode::usage);
    CHECK(refusal([] { parse_number_list("1,,2", ValueSource::argument("gravity")); }).first ==
          "gravity 1,,2: \"\" is not a finite number");
    CHECK(refusal([] { parse_number_list("1", ValueSource::option("--size"), 2, 3); }).first ==
          "--size 1: expected 2 to 3 comma-separated numbers");
}

TEST_CASE("value checks: motif sites")
{
    CHECK(refusal([] { check_site(1, 2, "honeycomb", ValueSource::option("--site")); }).second == ExitCode::ok);
    auto option = refusal([] { check_site(5, 1, "fcc", ValueSource::argument("--site")); });
    CHECK(option.first == "--site: site 5 does not exist; lattice fcc has sites 0 to 0");
    CHECK(option.second == ExitCode::input);
    CHECK(refusal([] { check_site(-1, 2, "honeycomb", {}); }).first ==
          "site -1 does not exist; lattice honeycomb has sites 0 to 1");
    auto located = refusal([] { at_source(ValueSource::json("s.json", "/lattices/0"), [] { fail_input("bad"); }); });
    CHECK(located.first == "s.json: /lattices/0: bad");
}

TEST_CASE("a setting named below the front ends is spelled by the one that shows the message")
{
    const std::string message = "a smaller " + setting_named("max_move") + " or more " + setting_named("dt");
    const auto option = [](std::string_view key) { return value_named(FrontEnd::command_line, key).name; };
    CHECK(spell_settings(message, option) == "a smaller --max-move or more --dt");
    CHECK(spell_settings(message, [](std::string_view key) { return std::string(key); }) ==
          "a smaller max_move or more dt");
    // Braces that hold no key are the message's own (a file name, a JSON text).
    CHECK(spell_settings("f{{A b}}.csv {{}} {{x", option) == "f{{A b}}.csv {{}} {{x");
}
