// The command line as the commands declare it: handles on CLI11's subcommands and
// options, so that only options.cpp and main.cpp include CLI11. Its header defines
// its whole parser inline and costs seconds of compilation in every unit that sees it.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace sphkern {
class SettingTable;
}

namespace sphkern::cli {

// One declared option: the CLI11 settings the commands use.
class Option {
public:
    explicit Option(CLI::Option* option) : option_(option) {}
    Option required();
    Option capture_default_str(); // show the default in --help
    Option expected(int values);  // a list of exactly this many values
    Option one_value_per_use();   // a repeatable option that takes only the word after it each time
    Option hidden();              // left out of --help (an old name kept to say the new one)
    Option excludes(Option other);
    Option excludes(const std::string& name);
    Option needs(Option other);
    Option check_non_negative();
    Option check_member(std::initializer_list<int> values);

private:
    CLI::Option* option_;
};

// A command (or the program) whose options are being declared, and after parsing, what was given.
// A subcommand's options are its settings (requests/settings): declared there once, with
// their names, help and defaults.
class Command {
public:
    explicit Command(CLI::App& app, const SettingTable* settings = nullptr) : app_(&app), settings_(settings) {}
    // The command of that name, with its table of settings.
    Command add_subcommand(const std::string& name, const std::string& description);
    // The option (or positional) of the setting `key` as the command's table declares it:
    // name, help, the default given to `value` and shown in --help where the table says; a
    // positional is required unless it takes a list. T: as add_option's, and bool for a flag.
    template <class T>
    Option add_setting(std::string_view key, T& value);
    // T: std::string, int, unsigned, long long, unsigned long long, std::size_t, double,
    // std::optional<int or double>, std::vector of std::string or double (options.cpp).
    template <class T>
    Option add_option(const std::string& name, T& value, const std::string& description);
    Option add_flag(const std::string& name, bool& value, const std::string& description);
    Option get_option(const std::string& name);
    std::size_t count(const std::string& name) const; // how often the option was given

private:
    CLI::App* app_;
    const SettingTable* settings_;
};

} // namespace sphkern::cli
