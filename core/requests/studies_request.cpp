#include "requests/studies_request.hpp"

#include "support/io/install_paths.hpp"
#include "support/io/json_input.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

namespace sphkern {

nlohmann::json studies_listing()
{
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(data_folder("studies"), ec))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    nlohmann::json list = nlohmann::json::array();
    for (const auto& file : files) {
        const auto study = read_json_file(file);
        list.push_back({{"name", file.stem().string()},
                        {"title", study.value("title", study.value("name", ""))},
                        {"kernels", study.value("kernels", nlohmann::json::array()).size()},
                        {"lattices", study.value("lattices", nlohmann::json::array())},
                        {"file", file.string()}});
    }
    return list;
}

void print_studies(const nlohmann::json& listing)
{
    for (const auto& s : listing) {
        std::string lattices;
        for (const auto& l : s["lattices"]) lattices += (lattices.empty() ? "" : ", ") + l.get<std::string>();
        fmt::print(results_file(), "{:<14} {}\n{:<14} {} kernel(s) on {}; {}\n", s["name"].get<std::string>(),
                   s["title"].get<std::string>(), "", s["kernels"].get<std::size_t>(), lattices,
                   s["file"].get<std::string>());
    }
}

} // namespace sphkern
