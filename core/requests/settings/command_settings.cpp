#include "requests/settings/command_settings.hpp"

#include "support/text/setting_names.hpp"

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

std::string spelled_message(FrontEnd front_end, std::string_view message)
{
    return spell_settings(message, [front_end](std::string_view key) {
        for (const auto& table : command_settings())
            for (const auto& s : table.settings()) {
                const std::string& name = front_end == FrontEnd::python ? s.keyword : s.option;
                if (s.key == key && !name.empty() && !s.positional) return name;
            }
        return value_named(front_end, key).name;
    });
}

const SettingTable& settings_of(std::string_view command)
{
    for (const auto& table : command_settings())
        if (table.command() == command) return table;
    throw std::logic_error("no settings declared for command " + std::string(command));
}

} // namespace sphkern
