// `sphkern studies`: the shipped studies, each with its title and what it runs.
#include "cli/command.hpp"
#include "support/io/results_output.hpp"

#include "support/io/install_paths.hpp"
#include "support/io/json_input.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>

namespace sphkern::cli {

Action add_studies_command(Command app)
{
    Command command = app.add_subcommand("studies", "List the shipped studies (run them with sphkern run NAME)");
    auto options = std::make_shared<CommonOptions>();
    add_json_option(command, *options);
    return [options] {
        std::vector<std::filesystem::path> files;
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(data_folder("studies"), ec))
            if (entry.path().extension() == ".json") files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        nlohmann::json list = nlohmann::json::array();
        for (const auto& file : files) {
            const auto study = read_json_file(file);
            list.push_back({{"name", file.stem().string()}, {"title", study.value("title", study.value("name", ""))},
                            {"kernels", study.value("kernels", nlohmann::json::array()).size()},
                            {"lattices", study.value("lattices", nlohmann::json::array())},
                            {"file", file.string()}});
        }
        if (options->json) {
            print_json(list);
            return 0;
        }
        for (const auto& s : list) {
            std::string lattices;
            for (const auto& l : s["lattices"]) lattices += (lattices.empty() ? "" : ", ") + l.get<std::string>();
            fmt::print(results_file(), "{:<14} {}\n{:<14} {} kernel(s) on {}; {}\n", s["name"].get<std::string>(),
                       s["title"].get<std::string>(), "", s["kernels"].get<std::size_t>(), lattices,
                       s["file"].get<std::string>());
        }
        return 0;
    };
}

} // namespace sphkern::cli
