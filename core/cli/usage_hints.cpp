#include "cli/usage_hints.hpp"

#include "support/text/value_checks.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <vector>

namespace sphkern::cli {

namespace {

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

// The nearest of `names` to `word`, case-insensitive, as " (did you mean "x"?)"; "" if none is close.
std::string nearest(const std::string& word, const std::vector<std::string>& names)
{
    std::vector<std::string> lowered;
    for (const auto& n : names) lowered.push_back(lower(n));
    const auto match = closest_match(lower(word), lowered);
    if (!match) return "";
    const auto at = std::find(lowered.begin(), lowered.end(), *match) - lowered.begin();
    return fmt::format(" (did you mean \"{}\"?)", names[static_cast<std::size_t>(at)]);
}

std::vector<std::string> command_names(const CLI::App& app)
{
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        names.push_back(sub->get_name());
    return names;
}

// The command being parsed, or nullptr before one was recognised.
const CLI::App* parsed_command(const CLI::App& app)
{
    const auto parsed = app.get_subcommands();
    return parsed.empty() ? nullptr : parsed.front();
}

std::vector<std::string> option_names(const CLI::App& command)
{
    std::vector<std::string> names;
    for (const CLI::Option* o : command.get_options())
        for (const auto& l : o->get_lnames()) names.push_back("--" + l);
    return names;
}

// The words CLI11 did not take, in the order they were typed (it lists them in its own).
std::vector<std::string> extras_in_order(const CLI::App& app, int argc, const char* const* argv)
{
    std::vector<std::string> remaining = app.remaining();
    if (const CLI::App* c = parsed_command(app)) {
        const auto more = c->remaining();
        remaining.insert(remaining.end(), more.begin(), more.end());
    }
    std::vector<std::string> ordered;
    for (int i = 1; i < argc; ++i)
        if (std::find(remaining.begin(), remaining.end(), argv[i]) != remaining.end() &&
            std::find(ordered.begin(), ordered.end(), argv[i]) == ordered.end())
            ordered.push_back(argv[i]);
    return ordered;
}

} // namespace

std::string usage_message(const CLI::App& app, const CLI::ParseError& error, int argc, const char* const* argv)
{
    const std::string what = error.what();
    const CLI::App* command = parsed_command(app);
    // A first word that names no command.
    if (!command) {
        for (int i = 1; i < argc; ++i) {
            const std::string word = argv[i];
            if (word.starts_with("-")) {
                if (word == "--log-level") ++i;
                continue;
            }
            return fmt::format("unknown command \"{}\"{}; the commands are {}", word, nearest(word, command_names(app)),
                               fmt::join(command_names(app), ", "));
        }
        return what;
    }
    // Words no option took: an unknown option is named with the nearest one.
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        const auto extras = extras_in_order(app, argc, argv);
        for (const auto& word : extras) {
            // sphkern's own options (--log-level) come before the command.
            const std::string name = word.substr(0, word.find('='));
            if (name.starts_with("--") && app.get_option_no_throw(name) != nullptr)
                return fmt::format("{} is sphkern's own option: give it before the command (sphkern {} VALUE {} ...)",
                                   name, name, command->get_name());
        }
        for (const auto& word : extras)
            if (word.starts_with("--"))
                return fmt::format("{}: unknown option \"{}\"{}; `sphkern {} --help` lists them", command->get_name(),
                                   word, nearest(word.substr(0, word.find('=')), option_names(*command)),
                                   command->get_name());
        if (!extras.empty())
            return fmt::format("{}: the arguments {} were not expected (see sphkern {} --help)", command->get_name(),
                               fmt::join(extras, " "), command->get_name());
    }
    // "Could not convert: --kmin = abc": the form a number takes.
    static const std::regex conversion(R"(Could not convert: (\S+) = (.*))");
    std::smatch m;
    if (std::regex_search(what, m, conversion))
        return fmt::format("{} {}: expected a number (such as 1.2 or 2e-3)", m[1].str(), m[2].str());
    return what + " (see sphkern --help)";
}

} // namespace sphkern::cli
