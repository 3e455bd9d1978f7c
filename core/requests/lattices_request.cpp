#include "requests/lattices_request.hpp"

#include "lattices/lattice_json.hpp"
#include "support/io/install_paths.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

namespace sphkern {

namespace {

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
        fmt::print(results_file(), "{:<12} {:>3} {:>5}  {}\n", lattice.name, lattice.dimension, lattice.sites(),
                   file.string());
    }
}

} // namespace

nlohmann::json lattices_listing()
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& name : shipped_lattice_names()) list.push_back(lattice_json(load_lattice(name)));
    return list;
}

void print_lattices(const nlohmann::json& listing)
{
    fmt::print(results_file(), "{:<12} {:>3} {:>5}  {:<44} {}\n", "name", "D", "sites", "a_p variants", "gravity");
    for (const auto& l : listing) {
        std::string coefficients, gravity;
        for (const auto& [name, value] : l["volume_coefficients"].items())
            coefficients += fmt::format("{}{}={:.6g}", coefficients.empty() ? "" : " ", name, value.get<double>());
        for (double g : l["gravity"]) gravity += fmt::format("{}{:.4g}", gravity.empty() ? "" : ",", g);
        fmt::print(results_file(), "{:<12} {:>3} {:>5}  {:<44} {}\n", l["name"].get<std::string>(),
                   l["dimension"].get<int>(), l["sites"].get<int>(), coefficients, gravity);
    }
    print_examples();
}

nlohmann::json lattice_description(const Lattice& lattice, double radius, const ValueSource& source)
{
    check_positive(radius, source);
    return lattice_description_json(lattice, radius);
}

void print_lattice_description(const Lattice& lattice, const nlohmann::json& d)
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
            shells += fmt::format("{}{:.4f} ({})", shells.empty() ? "" : ", ", s["radius"].get<double>(),
                                  s["count"].get<int>());
        fmt::print(results_file(), "  site {} at ({}) d: shells up to {} d: {}\n", site["site"].get<int>(), position,
                   d["shells_radius"].get<double>(), shells);
    }
}

} // namespace sphkern
