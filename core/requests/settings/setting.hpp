// One setting a command takes, declared once: its key, type, default, one line of help and
// how each front end spells it. The command line's options and Python's keywords are made
// from it (cli/options, python/setting_keywords); a test holds the docstrings to it.
#pragma once

#include "support/text/value_checks.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sphkern {

// What a setting holds, as both front ends give it: a number, a whole number, a word, a
// flag, or a list (numbers or words, repeatable or comma-separated).
enum class SettingType { number, integer, word, flag, list };

// The values a number may take, as its check says them: a count ("--steps 0, expected 1 to
// 1000") or an interval with its unit ("--dt 0.6: expected a number in (0, 0.5] (units of h / c)").
struct Bounds {
    double min = 0, max = 0;
    LowEnd low = LowEnd::closed;
    std::string unit; // after an interval: " (units of h / c)"
    bool count = false;
};

struct Setting {
    std::string key; // its name in a request's words, Python's spelling ("max_move")
    SettingType type = SettingType::number;
    std::string fallback;         // the default as text ("0.75", "voronoi", "0"); empty: none (absent, None)
    std::string help;             // one line: the option's help, and what sphkern.settings lists
    std::string option;           // the command line's "--max-move" or a positional's "kernel"; empty: none
    std::string keyword;          // Python's keyword; empty: none
    std::string study_key;        // a study section's JSON Pointer to it ("/grid", "/k/steps"); empty: none
    bool positional = false;      // before the options (kernel, lattice)
    bool required = false;        // no default in either front end (a positional but a list, unless optional())
    bool default_shown = true;    // --help shows the fallback
    bool hidden = false;          // left out of --help: an old name, kept to say the new one
    std::optional<Bounds> bounds; // checked by check_setting, whichever front end gave the value

    // Modifiers, for the tables' rows: another option or keyword, none in one front end.
    Setting& as_option(std::string name);
    Setting& as_keyword(std::string name);
    Setting& in_study(std::string pointer); // a study section's key below the section ("/path_points")
    Setting& command_line_only();
    Setting& python_only();
    Setting& default_hidden();                // --help leaves the fallback out ("the default: every core" in the help)
    Setting& optional();                      // a positional that may be left out (Python's None)
    Setting& mandatory();                     // an option that must be given (no default in either front end)
    Setting& old_name();                      // hidden, on the command line only
    Setting& counted(double min, double max); // min to max
    Setting& within(double min, double max, LowEnd low, std::string unit = {}); // [min, max] or (min, max]
};

// The rows of a table: the option is --key with - for _, the keyword the key.
Setting number(std::string key, std::string fallback, std::string help);
Setting integer(std::string key, std::string fallback, std::string help);
Setting word(std::string key, std::string fallback, std::string help);
Setting flag(std::string key, std::string help);
Setting list(std::string key, std::string help);
Setting positional(std::string key, std::string help);
Setting positional_list(std::string key, std::string help); // one or more words

// The value against the setting's bounds (none: any), refused naming `source` as the front end
// named it.
void check_setting(const Setting& setting, double value, const ValueSource& source);

// The settings of one command, in the order its --help lists them.
class SettingTable {
public:
    SettingTable(std::string command, std::vector<std::vector<Setting>> groups);
    const std::string& command() const { return command_; }
    const std::vector<Setting>& settings() const { return settings_; }
    // The setting of that key; std::logic_error for a key the command does not declare.
    const Setting& operator[](std::string_view key) const;

private:
    std::string command_;
    std::vector<Setting> settings_;
};

} // namespace sphkern
