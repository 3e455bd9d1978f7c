// `sphkern lattices`: the shipped lattices, their volume coefficients and gravity, and the examples.
#include "cli/command.hpp"
#include "lattices/lattice_json.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>

namespace sphkern::cli {

namespace {

void print_description(const Lattice& lattice, const nlohmann::json& d)
{
    fmt::print(results_file(), "{} ({}): {}D, {} site(s), from {}\n", lattice.name, lattice.title, lattice.dimension,
               lattice.sites(), lattice.file);
    fmt::print(results_file(), "  nearest-neighbour distance d = 1 ({:.10g} in the file's units)\n",
               lattice.file_nearest_distance);
    std::string coefficients;
    for (const auto& c : lattice.volume_coefficients) coefficients += fmt::format(" {}={:.10g}", c.name, c.value);
    fmt::print(results_file(), "  a_p:{}\n", coefficients);
    for (const auto& site : d["site_details"]) {
        std::string position, shells;
        for (double v : site["position"]) position += fmt::format("{}{:.6f}", position.empty() ? "" : ", ", v);
        for (const auto& s : site["shells"])
            shells += fmt::format("{}{:.4f} ({})", shells.empty() ? "" : ", ", s["radius"].get<double>(), s["count"].get<int>());
        fmt::print(results_file(), "  site {} at ({}) d: shells up to {} d: {}\n", site["site"].get<int>(), position,
                   d["shells_radius"].get<double>(), shells);
    }
}

// The example lattices shipped beside the others, used by their path.
void print_examples()
{
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(data_folder("lattices") / "examples", ec))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    if (files.empty()) return;
    std::sort(files.begin(), files.end());
    fmt::print(results_file(), "\nexamples (several sites; give the file):\n");
    for (const auto& file : files) {
        const auto lattice = read_lattice(file);
        fmt::print(results_file(), "{:<12} {:>3} {:>5}  {}\n", lattice.name, lattice.dimension, lattice.sites(), file.string());
    }
}

} // namespace

Action add_lattices_command(Command app)
{
    Command command = app.add_subcommand("lattices", "List the shipped lattices, or describe the ones named (or files)");
    struct Options : CommonOptions {
        std::vector<std::string> lattices;
        double radius = 3;
    };
    auto options = std::make_shared<Options>();
    command.add_option("lattice", options->lattices, "Lattice names or files to describe in full");
    command.add_option("--radius", options->radius, "Shells up to this radius, in d, when describing")
        .capture_default_str();
    add_json_option(command, *options);
    add_plugin_option(command, *options);
    return [options] {
        if (!options->plugins.empty()) discover_kernels(*options); // validated like everywhere
        if (!options->lattices.empty()) {
            nlohmann::json list = nlohmann::json::array();
            for (const auto& spec : options->lattices) {
                auto lattice = load_lattice(spec);
                auto d = lattice_description_json(lattice, options->radius);
                if (options->json) list.push_back(d);
                else print_description(lattice, d);
            }
            if (options->json) print_json(list);
            return 0;
        }
        nlohmann::json list = nlohmann::json::array();
        for (const auto& name : shipped_lattice_names()) list.push_back(lattice_json(load_lattice(name)));
        if (options->json) {
            print_json(list);
            return 0;
        }
        fmt::print(results_file(), "{:<12} {:>3} {:>5}  {:<44} {}\n", "name", "D", "sites", "a_p variants", "gravity");
        for (const auto& l : list) {
            std::string coefficients, gravity;
            for (const auto& [name, value] : l["volume_coefficients"].items())
                coefficients += fmt::format("{}{}={:.6g}", coefficients.empty() ? "" : " ", name, value.get<double>());
            for (double g : l["gravity"]) gravity += fmt::format("{}{:.4g}", gravity.empty() ? "" : ",", g);
            fmt::print(results_file(), "{:<12} {:>3} {:>5}  {:<44} {}\n", l["name"].get<std::string>(),
                       l["dimension"].get<int>(), l["sites"].get<int>(), coefficients, gravity);
        }
        print_examples();
        return 0;
    };
}

} // namespace sphkern::cli
