// The one set of checks for values that enter from outside (a command-line option, a
// Python argument, a study file): the k range, names, lists of numbers, motif sites.
// Each failure is an Error whose message starts with where the value came from.
#pragma once

#include "support/error.hpp"

#include <cstddef>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sphkern {

// Where a value came from: an option ("--k"), an argument ("k"), or a file and JSON
// Pointer ("s.json: /k"), and the exit code its refusal carries.
struct ValueSource {
    std::string name;
    ExitCode code = ExitCode::input;

    static ValueSource option(std::string option) { return {std::move(option), ExitCode::usage}; }
    static ValueSource argument(std::string argument) { return {std::move(argument), ExitCode::input}; }
    static ValueSource json(const std::string& file, const std::string& pointer)
    {
        return {file + ": " + pointer, ExitCode::input};
    }

    // "--k -1" for an option, "k = -1" for an argument.
    std::string about(double value) const;
    // Throws the problem, prefixed with the name ("--site: ...") when there is one.
    [[noreturn]] void fail(const std::string& problem, ErrorKind kind = ErrorKind::general) const;
};

// Runs f; an Error it throws is thrown again with the source's name in front, and a value
// out of range (exit 2) with the source's exit code: a file's value is an input (exit 3).
template <class F>
decltype(auto) at_source(const ValueSource& source, F&& f)
{
    try {
        return f();
    } catch (const Error& e) {
        throw Error(e.code() == ExitCode::usage ? source.code : e.code(), source.name + ": " + e.what(), e.kind());
    }
}

// How each front end names a value, from its key in Python's spelling ("max_move"): the
// option "--max-move" (exit 2 out of range) or the argument "max_move" (exit 3).
enum class FrontEnd { command_line, python };
ValueSource value_named(FrontEnd front_end, std::string_view key);

// "give one of --eta, --nh and --k" (or eta, nh and k) when more than one of `given` is set.
void require_at_most_one(std::initializer_list<std::pair<bool, const ValueSource*>> given);

// The smoothing coefficient k = h/d: finite, in (0, 100].
constexpr double k_limit = 100;
bool k_in_range(double k);
// "--k -1 is not allowed, expected a number in (0, 100]" (and `hint` after it).
void check_k(double k, const ValueSource& source, std::string_view hint = {});

// A number in [min, max] (NaN refused): "--points 0, expected 1 to 100000", "steps = 0, expected 1 to 2000".
void check_range(double value, double min, double max, const ValueSource& source);
// A number in [min, max], or (min, max] where `low` is open (NaN refused), with the unit after
// the interval: "--dt 0.6: expected a number in (0, 0.5] (units of h / c)", "eta = 0: expected ...".
enum class LowEnd { closed, open };
void check_number(double value, double min, double max, LowEnd low, const ValueSource& source,
                  std::string_view unit = {});
// A positive finite number: "--rho0 0: expected a positive finite number".
void check_positive(double value, const ValueSource& source);
// The intervals of a k scan (roots --stability, stability over k): 1 to 2000.
constexpr int max_scan_steps = 2000;

// A k interval: 0 < min < max <= 100, or min <= max where one point is a valid interval.
enum class IntervalEnds { distinct, may_meet };
// Named as one value: "k interval: [1.3, 1] is not allowed, expected 0 < min < max <= 100".
void check_k_interval(double k_min, double k_max, const ValueSource& interval,
                      IntervalEnds kind = IntervalEnds::distinct);
// Two values: "--kmin 1.2 --kmax 1: expected 0 < kmin < kmax <= 100" for options, "kmin = 1.2,
// kmax = 1: ..." for arguments (the exit code is min's).
void check_k_interval(double k_min, double k_max, const ValueSource& min, const ValueSource& max,
                      IntervalEnds kind = IntervalEnds::distinct);

// A name of 1 to max_length characters of [a-z0-9_] and the characters in `extra`.
bool is_identifier(std::string_view name, std::string_view extra = {}, std::size_t max_length = 64);

// The closest of `candidates` to `word` by edit distance, if any is close enough.
std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates);
// " (did you mean \"x\"?)" for the closest candidate, or "" when none is close.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

// "a,b,c": finite numbers, between min_count and max_count of them; an item that is no
// number is refused as "--shells 1,x: \"x\" is not a finite number".
std::vector<double> parse_number_list(const std::string& text, const ValueSource& source, std::size_t min_count = 1,
                                      std::size_t max_count = std::numeric_limits<std::size_t>::max());

// "lattice fcc has sites 0 to 0".
std::string site_range(std::string_view lattice, int site_count);
// A motif site: "--site: site 5 does not exist; lattice fcc has sites 0 to 0".
void check_site(int site, int site_count, std::string_view lattice, const ValueSource& source);

} // namespace sphkern
