#include "study/declared_keys.hpp"

#include "requests/settings/command_settings.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace sphkern {

namespace {

// "/k/steps" as {"k", "steps"}.
std::vector<std::string> tokens_of(const std::string& pointer)
{
    std::vector<std::string> tokens;
    for (std::size_t at = 1; at <= pointer.size();) {
        const std::size_t end = std::min(pointer.find('/', at), pointer.size());
        tokens.push_back(pointer.substr(at, end - at));
        at = end + 1;
    }
    return tokens;
}

const Setting& study_setting(std::string_view command, std::string_view key)
{
    const Setting& setting = settings_of(command)[key];
    if (setting.study_key.empty())
        throw std::logic_error("the setting " + std::string(key) + " of " + std::string(command) + " has no study key");
    return setting;
}

} // namespace

std::vector<std::string> declared_study_keys(std::string_view command, std::vector<std::string> others)
{
    std::vector<std::string> keys;
    for (const Setting& s : settings_of(command).settings()) {
        if (s.study_key.empty()) continue;
        const std::string first = tokens_of(s.study_key).front();
        if (std::find(keys.begin(), keys.end(), first) == keys.end()) keys.push_back(first);
    }
    for (auto& key : others)
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(std::move(key));
    return keys;
}

std::optional<JsonNode> declared_node(const JsonNode& section, std::string_view command, std::string_view key)
{
    std::optional<JsonNode> node = section;
    for (const auto& token : tokens_of(study_setting(command, key).study_key)) {
        if (!node->is_object()) return std::nullopt; // the object's own reader names its type
        node = node->find(token);
        if (!node) return std::nullopt;
    }
    return node;
}

std::optional<double> declared_number(const JsonNode& section, std::string_view command, std::string_view key)
{
    const auto node = declared_node(section, command, key);
    if (!node) return std::nullopt;
    const Setting& setting = study_setting(command, key);
    constexpr auto int_min = std::numeric_limits<int>::min(), int_max = std::numeric_limits<int>::max();
    const double v =
        setting.type == SettingType::integer ? static_cast<double>(node->integer_in(int_min, int_max)) : node->number();
    check_setting(setting, v, ValueSource::json(node->file(), node->path()));
    return v;
}

} // namespace sphkern
