// The one unit (with main.cpp) that includes CLI11: every add_option the commands use is
// instantiated here, once.
#include "cli/options.hpp"

#include "requests/settings/command_settings.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace sphkern::cli {

Option Option::required()
{
    option_->required();
    return *this;
}

Option Option::capture_default_str()
{
    option_->capture_default_str();
    return *this;
}

Option Option::expected(int values)
{
    option_->expected(values);
    return *this;
}

Option Option::one_value_per_use()
{
    // A list option otherwise takes every word up to the next option: `--plugin a.so kernel
    // lattice` would swallow the kernel and the lattice.
    option_->allow_extra_args(false);
    return *this;
}

Option Option::hidden()
{
    option_->group("");
    return *this;
}

Option Option::excludes(Option other)
{
    option_->excludes(other.option_);
    return *this;
}

Option Option::excludes(const std::string& name)
{
    option_->excludes(name);
    return *this;
}

Option Option::needs(Option other)
{
    option_->needs(other.option_);
    return *this;
}

Option Option::check_non_negative()
{
    option_->check(CLI::NonNegativeNumber);
    return *this;
}

Option Option::check_member(std::initializer_list<int> values)
{
    option_->check(CLI::IsMember(values));
    return *this;
}

Command Command::add_subcommand(const std::string& name, const std::string& description)
{
    return Command(*app_->add_subcommand(name, description), &settings_of(name));
}

namespace {

// The table's default into the option's variable: a number, a word, a flag. A list or an
// optional stays empty: no default, or one --help does not show, which Python spells for
// "not given" (threads=0, path=0); a plain number must have one.
template <class T>
void give_default(const Setting& s, T& value, const std::string& command)
{
    if constexpr (std::is_same_v<T, bool>) value = s.fallback == "true";
    else if constexpr (std::is_same_v<T, std::string>) value = s.fallback;
    else if constexpr (std::is_arithmetic_v<T>) {
        if (s.fallback.empty() && !s.required)
            throw std::logic_error("setting " + s.key + " of " + command + " declares no default for its number");
        if (!s.fallback.empty()) value = static_cast<T>(std::stod(s.fallback));
    } else if (!s.fallback.empty() && s.default_shown)
        throw std::logic_error("setting " + s.key + " of " + command + " has a default its option cannot hold");
}

} // namespace

template <class T>
Option Command::add_setting(std::string_view key, T& value)
{
    if (!settings_) throw std::logic_error("the program's options are not settings");
    const Setting& s = (*settings_)[key];
    if (s.option.empty()) throw std::logic_error("setting " + s.key + " is not on the command line");
    give_default(s, value, settings_->command());
    if constexpr (std::is_same_v<T, bool>) return add_flag(s.option, value, s.help);
    else {
        Option option = add_option(s.option, value, s.help);
        if (s.required) option.required();
        if (s.default_shown && !s.fallback.empty()) option.capture_default_str();
        if (s.hidden) option.hidden();
        return option;
    }
}

template <class T>
Option Command::add_option(const std::string& name, T& value, const std::string& description)
{
    return Option(app_->add_option(name, value, description));
}

Option Command::add_flag(const std::string& name, bool& value, const std::string& description)
{
    return Option(app_->add_flag(name, value, description));
}

Option Command::get_option(const std::string& name) { return Option(app_->get_option(name)); }

std::size_t Command::count(const std::string& name) const { return app_->count(name); }

template Option Command::add_option(const std::string&, std::string&, const std::string&);
template Option Command::add_option(const std::string&, int&, const std::string&);
template Option Command::add_option(const std::string&, unsigned&, const std::string&);
template Option Command::add_option(const std::string&, long long&, const std::string&);
template Option Command::add_option(const std::string&, unsigned long long&, const std::string&);
template Option Command::add_option(const std::string&, std::size_t&, const std::string&);
template Option Command::add_option(const std::string&, double&, const std::string&);
template Option Command::add_option(const std::string&, std::optional<int>&, const std::string&);
template Option Command::add_option(const std::string&, std::optional<double>&, const std::string&);
template Option Command::add_option(const std::string&, std::vector<std::string>&, const std::string&);
template Option Command::add_option(const std::string&, std::vector<double>&, const std::string&);
template Option Command::add_setting(std::string_view, std::string&);
template Option Command::add_setting(std::string_view, int&);
template Option Command::add_setting(std::string_view, unsigned&);
template Option Command::add_setting(std::string_view, long long&);
template Option Command::add_setting(std::string_view, unsigned long long&);
template Option Command::add_setting(std::string_view, std::size_t&);
template Option Command::add_setting(std::string_view, double&);
template Option Command::add_setting(std::string_view, bool&);
template Option Command::add_setting(std::string_view, std::optional<int>&);
template Option Command::add_setting(std::string_view, std::optional<double>&);
template Option Command::add_setting(std::string_view, std::vector<std::string>&);
template Option Command::add_setting(std::string_view, std::vector<double>&);

} // namespace sphkern::cli
