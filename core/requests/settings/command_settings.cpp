#include "requests/settings/command_settings.hpp"

#include <stdexcept>
#include <string>

namespace sphkern {

const std::vector<SettingTable>& command_settings()
{
    static const std::vector<SettingTable> tables{run_settings(),      kernels_settings(),   check_settings(),
                                                  lattices_settings(), shells_settings(),    eps_settings(),
                                                  assess_settings(),   roots_settings(),     surface_settings(),
                                                  block_settings(),    design_settings(),    stability_settings(),
                                                  spectrum_settings(), particles_settings(), relax_settings(),
                                                  pairing_settings(),  studies_settings()};
    return tables;
}

const SettingTable& settings_of(std::string_view command)
{
    for (const auto& table : command_settings())
        if (table.command() == command) return table;
    throw std::logic_error("no settings declared for command " + std::string(command));
}

} // namespace sphkern
