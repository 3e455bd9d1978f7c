// Every command's table of settings (one file each, <command>_settings.cpp): what the command
// line's options and Python's keywords are made from.
#pragma once

#include "requests/settings/setting.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace sphkern {

SettingTable run_settings();
SettingTable kernels_settings();
SettingTable check_settings();
SettingTable lattices_settings();
SettingTable shells_settings();
SettingTable eps_settings();
SettingTable assess_settings();
SettingTable roots_settings();
SettingTable surface_settings();
SettingTable block_settings();
SettingTable design_settings();
SettingTable stability_settings();
SettingTable spectrum_settings();
SettingTable particles_settings();
SettingTable relax_settings();
SettingTable pairing_settings();
SettingTable studies_settings();

// Every command's table, in the order of `sphkern --help`, made once.
const std::vector<SettingTable>& command_settings();
// The table of one command; std::logic_error for a command without one.
const SettingTable& settings_of(std::string_view command);

// A message with the settings that layers below requests/ named (setting_named) spelled as
// the front end spells them: the option or keyword a table gives the key ("--ap", "a_p"),
// else the front end's plain spelling of it ("--memory-limit", "memory_limit").
std::string spelled_message(FrontEnd front_end, std::string_view message);

} // namespace sphkern
