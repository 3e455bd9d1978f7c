// `sphkern run`: placeholder replaced below.
#include "cli/command.hpp"
namespace sphkern::cli {
Action add_run_command(CLI::App& app)
{
    app.add_subcommand("run", "Run a study");
    return [] { return 0; };
}
} // namespace sphkern::cli
