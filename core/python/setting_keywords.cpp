#include "setting_keywords.hpp"

#include "support/error.hpp"
#include "support/text/value_checks.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;

namespace sphkern {

const Setting& SettingKeywords::keyword_setting(std::string_view key) const
{
    const Setting& s = table_[key];
    if (s.keyword.empty()) throw std::logic_error("setting " + s.key + " of " + table_.command() + " is not in Python");
    return s;
}

py::arg SettingKeywords::required(std::string_view key) const
{
    const Setting& s = keyword_setting(key);
    // Required here though the command line may take another setting instead (eps's k: code_k).
    if (!s.fallback.empty()) throw std::logic_error("setting " + s.key + " of " + table_.command() + " has a default");
    return py::arg(s.keyword.c_str()); // the table lives as long as the program
}

namespace {

// The default as Python gives it: a float, an int, a bool, a str, or None.
py::object default_of(const Setting& s)
{
    if (s.fallback.empty() || s.type == SettingType::list) return py::none();
    switch (s.type) {
    case SettingType::number: return py::float_(std::stod(s.fallback));
    case SettingType::integer: return py::int_(std::stoll(s.fallback));
    case SettingType::flag: return py::bool_(s.fallback == "true");
    case SettingType::word:
    case SettingType::list: break;
    }
    return py::str(s.fallback);
}

py::object text_or_none(const std::string& text) { return text.empty() ? py::object(py::none()) : py::str(text); }

const char* type_name(SettingType type)
{
    switch (type) {
    case SettingType::number: return "number";
    case SettingType::integer: return "integer";
    case SettingType::word: return "word";
    case SettingType::flag: return "flag";
    case SettingType::list: break;
    }
    return "list";
}

// The values a number may take: {"min", "max", "low": "open" or "closed", "unit", "count"}, or None.
py::object bounds_of(const Setting& s)
{
    if (!s.bounds) return py::none();
    py::dict b;
    b["min"] = s.bounds->min, b["max"] = s.bounds->max, b["unit"] = s.bounds->unit, b["count"] = s.bounds->count;
    b["low"] = s.bounds->low == LowEnd::open ? "open" : "closed";
    return b;
}

} // namespace

py::arg_v SettingKeywords::operator()(std::string_view key) const
{
    const Setting& s = keyword_setting(key);
    if (s.required) throw std::logic_error("setting " + s.key + " of " + table_.command() + " is required");
    return py::arg(s.keyword.c_str()) = default_of(s);
}

py::list settings_listing(const std::string& command)
{
    const SettingTable* table = nullptr;
    std::vector<std::string> names;
    for (const auto& t : command_settings()) {
        names.push_back(t.command());
        if (t.command() == command) table = &t;
    }
    if (!table)
        throw Error(ExitCode::usage,
                    "command: unknown command \"" + one_line(command) + "\"" + did_you_mean(command, names),
                    ErrorKind::unknown_name);
    py::list rows;
    for (const auto& s : table->settings()) {
        py::dict row;
        row["key"] = s.key, row["type"] = type_name(s.type), row["default"] = default_of(s), row["help"] = s.help;
        row["option"] = text_or_none(s.option), row["keyword"] = text_or_none(s.keyword);
        row["study"] = text_or_none(s.study_key);
        row["positional"] = s.positional, row["required"] = s.required, row["hidden"] = s.hidden;
        row["bounds"] = bounds_of(s);
        rows.append(row);
    }
    return rows;
}

} // namespace sphkern
