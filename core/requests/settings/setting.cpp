#include "requests/settings/setting.hpp"

#include <algorithm>
#include <stdexcept>

namespace sphkern {

namespace {

Setting row(std::string key, SettingType type, std::string fallback, std::string help)
{
    std::string option = "--" + key;
    std::replace(option.begin(), option.end(), '_', '-');
    Setting s;
    s.keyword = key;
    s.key = std::move(key), s.type = type, s.fallback = std::move(fallback), s.help = std::move(help);
    s.option = std::move(option);
    return s;
}

} // namespace

Setting& Setting::as_option(std::string name)
{
    option = std::move(name);
    return *this;
}

Setting& Setting::as_keyword(std::string name)
{
    keyword = std::move(name);
    return *this;
}

Setting& Setting::in_study(std::string pointer)
{
    study_key = std::move(pointer);
    return *this;
}

Setting& Setting::command_line_only() { return as_keyword({}); }

Setting& Setting::python_only() { return as_option({}); }

Setting& Setting::default_hidden()
{
    default_shown = false;
    return *this;
}

Setting& Setting::optional()
{
    required = false;
    return *this;
}

Setting& Setting::mandatory()
{
    required = true;
    return *this;
}

Setting& Setting::old_name()
{
    hidden = true;
    return command_line_only();
}

Setting& Setting::counted(double min, double max)
{
    bounds = Bounds{min, max, LowEnd::closed, {}, true};
    return *this;
}

Setting& Setting::within(double min, double max, LowEnd low, std::string unit)
{
    bounds = Bounds{min, max, low, std::move(unit), false};
    return *this;
}

void check_setting(const Setting& setting, double value, const ValueSource& source)
{
    if (!setting.bounds) return;
    const Bounds& b = *setting.bounds;
    if (b.count) check_range(value, b.min, b.max, source);
    else check_number(value, b.min, b.max, b.low, source, b.unit);
}

Setting number(std::string key, std::string fallback, std::string help)
{
    return row(std::move(key), SettingType::number, std::move(fallback), std::move(help));
}

Setting integer(std::string key, std::string fallback, std::string help)
{
    return row(std::move(key), SettingType::integer, std::move(fallback), std::move(help));
}

Setting word(std::string key, std::string fallback, std::string help)
{
    return row(std::move(key), SettingType::word, std::move(fallback), std::move(help));
}

Setting flag(std::string key, std::string help)
{
    Setting s = row(std::move(key), SettingType::flag, "false", std::move(help));
    s.default_shown = false;
    return s;
}

Setting list(std::string key, std::string help) { return row(std::move(key), SettingType::list, {}, std::move(help)); }

Setting positional(std::string key, std::string help)
{
    Setting s = row(key, SettingType::word, {}, std::move(help));
    s.option = std::move(key);
    s.positional = s.required = true;
    return s;
}

Setting positional_list(std::string key, std::string help)
{
    Setting s = positional(std::move(key), std::move(help));
    s.type = SettingType::list;
    s.required = false;
    return s;
}

SettingTable::SettingTable(std::string command, std::vector<std::vector<Setting>> groups) : command_(std::move(command))
{
    for (auto& group : groups)
        for (auto& s : group) {
            if (std::any_of(settings_.begin(), settings_.end(), [&](const Setting& t) { return t.key == s.key; }))
                throw std::logic_error("setting " + s.key + " declared twice for " + command_);
            settings_.push_back(std::move(s));
        }
}

const Setting& SettingTable::operator[](std::string_view key) const
{
    for (const auto& s : settings_)
        if (s.key == key) return s;
    throw std::logic_error("command " + command_ + " declares no setting " + std::string(key));
}

} // namespace sphkern
