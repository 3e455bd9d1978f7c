#include "requests/settings/shared_settings.hpp"

#include "codes/code_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace sphkern {

Setting kernel_name() { return positional("kernel", "Kernel name or plugin file"); }

Setting lattice_name() { return positional("lattice", "Lattice name or file"); }

std::vector<Setting> evaluation_settings()
{
    return {
        word("a_p", "voronoi", "Volume coefficient: a name the lattice offers or a positive number").as_option("--ap"),
        list("gravity", "Gravity direction x,y[,z] (default: the lattice's)"),
        integer("site", "0", "Motif site of the particle"),
        list("shells", "Sum over these shell radii only (in d, comma-separated), as the paper does"),
        flag("continue_past_support",
             "Evaluate the kernel's formula past q = R instead of truncating (needs --shells)")};
}

Setting code_choice()
{
    std::vector<std::string> names;
    for (const auto& p : code_profiles()) names.push_back(p.name);
    return word("code", "",
                fmt::format("Give the resolution as an SPH code sets it: {}, with its parameter below",
                            fmt::join(names, ", ")));
}

namespace {

// The first code of each parameter (gadget2 and gadget4 share nngb), in the table's order.
std::vector<const CodeProfile*> one_per_parameter()
{
    std::vector<const CodeProfile*> first;
    for (const auto& p : code_profiles())
        if (std::none_of(first.begin(), first.end(), [&](const CodeProfile* q) { return q->parameter == p.parameter; }))
            first.push_back(&p);
    return first;
}

} // namespace

std::vector<Setting> code_parameters(const std::vector<std::string>& skip)
{
    std::vector<Setting> settings;
    for (const CodeProfile* p : one_per_parameter()) {
        if (std::find(skip.begin(), skip.end(), p->parameter) != skip.end()) continue;
        // The codes that share a parameter are named together.
        std::vector<std::string> codes;
        for (const auto& q : code_profiles())
            if (q.parameter == p->parameter) codes.push_back(q.name);
        settings.push_back(
            number(p->parameter, "", fmt::format("With --code {}: {}", fmt::join(codes, " or "), p->parameter_help))
                .command_line_only());
    }
    return settings;
}

std::vector<Setting> parameter_ranges()
{
    std::vector<Setting> settings;
    for (const CodeProfile* p : one_per_parameter())
        settings.push_back(
            list(p->parameter + "_range",
                 fmt::format("Particle file: sweep {} over [A, B] (--steps), and find the value the set needs",
                             p->parameter)));
    return settings;
}

Setting code_value()
{
    std::vector<std::string> parameters;
    for (const CodeProfile* p : one_per_parameter()) parameters.push_back(p->parameter);
    return number("value", "", fmt::format("The code's parameter ({})", fmt::join(parameters, ", "))).python_only();
}

std::vector<Setting> source_settings()
{
    return {list("size", "Lattice: cells of the periodic block, N1,N2[,N3]"),
            word("cell", "", "Lattice: the cell --size counts, primitive (default) or rectangular (a rectangular box)"),
            number("sigma", "0", "Lattice: Gaussian displacement per axis, in units of d").default_hidden(),
            integer("seed", "1", "Lattice and poisson: the random seed"),
            integer("count", "", "Poisson: number of particles"),
            integer("dim", "",
                    "Poisson: 2 or 3 (default 3); file: 2 reads a 3-column set with one constant coordinate"),
            list("box", "Poisson: the box sides (default 1); file: a periodic box Lx,Ly[,Lz] from the origin"),
            number("particle_radius", "",
                   "SPlisHSPlasH VTK file: the scene's particle radius r (the file holds none); h = r, support 4 r"),
            word("array", "",
                 "PySPH file: the particle array, or A,B,...: measured on A, with the particles of all as neighbours")};
}

std::vector<Setting> except_in_python(std::vector<Setting> settings, const std::vector<std::string>& kept)
{
    for (auto& s : settings)
        if (std::find(kept.begin(), kept.end(), s.key) == kept.end()) s.command_line_only();
    return settings;
}

Setting h_over_l_setting(std::string help)
{
    return number("h_over_l", "", std::move(help)).within(0, 100, LowEnd::open);
}

Setting nh_setting()
{
    return number("nh", "", "h from the neighbour number N_H = c_D (R h)^D n")
        .within(1, 1e5, LowEnd::closed, " (neighbours)");
}

Setting kernel_parameters() { return list("params", "Kernel parameter NAME=VALUE (repeatable)").as_option("--set"); }

Setting plugin_files() { return list("plugin", "Load this kernel plugin file too (repeatable)").command_line_only(); }

Setting json_output() { return flag("json", "Print machine-readable JSON on stdout").command_line_only(); }

} // namespace sphkern
