// A command's keywords as its table of settings declares them (requests/settings): the name
// and the default of each, so that the function's signature and the command line's options
// are made from the same rows.
#pragma once

#include "requests/settings/command_settings.hpp"

#include <pybind11/pybind11.h>

#include <string_view>

namespace sphkern {

class SettingKeywords {
public:
    explicit SettingKeywords(std::string_view command) : table_(settings_of(command)) {}
    // A keyword without a default (kernel, lattice); std::logic_error if the table gives one.
    pybind11::arg required(std::string_view key) const;
    // A keyword with the table's default: a float, an int, a str, a bool, or None.
    pybind11::arg_v operator()(std::string_view key) const;

private:
    const Setting& keyword_setting(std::string_view key) const;
    const SettingTable& table_;
};

// sphkern.settings(command): the command's table as a list of dicts; sphkern.UnknownName for
// a name that is no command.
pybind11::list settings_listing(const std::string& command);

} // namespace sphkern
