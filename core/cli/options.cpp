// The one unit (with main.cpp) that includes CLI11: every add_option the commands use is
// instantiated here, once.
#include "cli/options.hpp"

#include <CLI/CLI.hpp>

#include <optional>
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

Option Option::check_range(int min, int max)
{
    option_->check(CLI::Range(min, max));
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
    return Command(*app_->add_subcommand(name, description));
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

} // namespace sphkern::cli
