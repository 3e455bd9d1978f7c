#include "setting_keywords.hpp"

#include <stdexcept>
#include <string>

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

py::arg_v SettingKeywords::operator()(std::string_view key) const
{
    const Setting& s = keyword_setting(key);
    if (s.required) throw std::logic_error("setting " + s.key + " of " + table_.command() + " is required");
    const py::arg name(s.keyword.c_str());
    if (s.fallback.empty() || s.type == SettingType::list) return name = py::none();
    switch (s.type) {
    case SettingType::number: return name = py::float_(std::stod(s.fallback));
    case SettingType::integer: return name = py::int_(std::stoll(s.fallback));
    case SettingType::flag: return name = py::bool_(s.fallback == "true");
    case SettingType::word:
    case SettingType::list: break;
    }
    return name = py::str(s.fallback);
}

} // namespace sphkern
