#include "support/text/value_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace sphkern {

std::string ValueSource::about(double value) const
{
    return fmt::format("{}{}{}", name, name.rfind("-", 0) == 0 ? " " : " = ", value);
}

void ValueSource::fail(const std::string& problem, ErrorKind kind) const
{
    throw Error(code, name.empty() ? problem : name + ": " + problem, kind);
}

ValueSource value_named(FrontEnd front_end, std::string_view key)
{
    if (front_end == FrontEnd::python) return ValueSource::argument(std::string(key));
    std::string option = "--" + std::string(key);
    std::replace(option.begin(), option.end(), '_', '-');
    return ValueSource::option(option);
}

void require_at_most_one(std::initializer_list<std::pair<bool, const ValueSource*>> given)
{
    int count = 0;
    std::string names;
    const ValueSource* first = nullptr;
    std::size_t i = 0;
    for (const auto& [set, source] : given) {
        count += set;
        if (!first) first = source;
        names += (i == 0 ? "" : i + 1 == given.size() ? " and " : ", ") + source->name;
        ++i;
    }
    if (count > 1) throw Error(first->code, "give one of " + names);
}

bool k_in_range(double k) { return std::isfinite(k) && k > 0 && k <= k_limit; }

void check_k(double k, const ValueSource& source, std::string_view hint)
{
    if (!k_in_range(k))
        throw Error(source.code,
                    fmt::format("{} is not allowed, expected a number in (0, 100]{}", source.about(k), hint));
}

void check_range(double value, double min, double max, const ValueSource& source)
{
    if (!(value >= min && value <= max))
        throw Error(source.code, fmt::format("{}, expected {} to {}", source.about(value), min, max));
}

void check_number(double value, double min, double max, LowEnd low, const ValueSource& source, std::string_view unit)
{
    const bool above = low == LowEnd::open ? value > min : value >= min;
    if (!(above && value <= max))
        throw Error(source.code, fmt::format("{}: expected a number in {}{}, {}]{}", source.about(value),
                                             low == LowEnd::open ? "(" : "[", min, max, unit));
}

void check_positive(double value, const ValueSource& source)
{
    if (!(std::isfinite(value) && value > 0))
        throw Error(source.code, source.about(value) + ": expected a positive finite number");
}

namespace {

bool valid_interval(double k_min, double k_max, IntervalEnds kind)
{
    const bool ordered = kind == IntervalEnds::distinct ? k_min < k_max : k_min <= k_max;
    return k_in_range(k_min) && k_in_range(k_max) && ordered;
}

std::string bare(const std::string& option)
{
    return option.substr(std::min(option.find_first_not_of('-'), option.size()));
}

} // namespace

void check_k_interval(double k_min, double k_max, const ValueSource& interval, IntervalEnds kind)
{
    if (!valid_interval(k_min, k_max, kind))
        throw Error(interval.code,
                    fmt::format("{}: [{}, {}] is not allowed, expected 0 < min {} max <= 100", interval.name, k_min,
                                k_max, kind == IntervalEnds::distinct ? "<" : "<="));
}

void check_k_interval(double k_min, double k_max, const ValueSource& min, const ValueSource& max, IntervalEnds kind)
{
    if (!valid_interval(k_min, k_max, kind))
        throw Error(min.code, fmt::format("{}{}{}: expected 0 < {} {} {} <= 100", min.about(k_min),
                                          min.name.rfind("-", 0) == 0 ? " " : ", ", max.about(k_max), bare(min.name),
                                          kind == IntervalEnds::distinct ? "<" : "<=", bare(max.name)));
}

bool is_identifier(std::string_view name, std::string_view extra, std::size_t max_length)
{
    if (name.empty() || name.size() > max_length) return false;
    return std::all_of(name.begin(), name.end(), [&](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || extra.find(c) != std::string_view::npos;
    });
}

namespace {

std::size_t edit_distance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

} // namespace

std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates)
{
    std::optional<std::string> best;
    std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const auto& candidate : candidates) {
        std::size_t distance = edit_distance(word, candidate);
        if (distance < best_distance) {
            best_distance = distance;
            best = candidate;
        }
    }
    return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates)
{
    auto s = closest_match(word, candidates);
    return s ? " (did you mean \"" + *s + "\"?)" : "";
}

std::vector<double> parse_number_list(const std::string& text, const ValueSource& source, std::size_t min_count,
                                      std::size_t max_count)
{
    std::vector<double> values;
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || !end || *end != '\0' || !std::isfinite(v))
            throw Error(source.code,
                        source.name + " " + one_line(text) + ": \"" + one_line(item) + "\" is not a finite number");
        values.push_back(v);
    }
    if (values.size() < min_count || values.size() > max_count)
        throw Error(source.code, source.name + " " + one_line(text) + ": expected " + std::to_string(min_count) +
                                     (max_count > min_count ? " to " + std::to_string(max_count) : "") +
                                     " comma-separated numbers");
    return values;
}

std::string site_range(std::string_view lattice, int site_count)
{
    return fmt::format("lattice {} has sites 0 to {}", lattice, site_count - 1);
}

void check_site(int site, int site_count, std::string_view lattice, const ValueSource& source)
{
    if (site < 0 || site >= site_count)
        source.fail(fmt::format("site {} does not exist; {}", site, site_range(lattice, site_count)));
}

} // namespace sphkern
