#include "requests/settings/command_settings.hpp"

#include "requests/settings/shared_settings.hpp"

namespace sphkern {

SettingTable run_settings()
{
    return {"run",
            {{positional("study", "Study file, or the name of a shipped study").optional(),
              word("output", "", "Results folder (default: sphkern-results/<study name>)").as_option("-o,--output"),
              flag("no_plots", "Do not draw the figures"),
              word("format", "svg", "Figure formats, comma-separated: svg, png, pdf"),
              flag("force", "Replace an existing results folder"),
              word("reproduce", "",
                   "Run the study a results.json records again and say whether the numbers agree (exit 1 if not)"),
              plugin_files()}}};
}

} // namespace sphkern
