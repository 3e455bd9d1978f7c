// A reference table (share/reference): the roots a publication prints for one lattice,
// volume coefficient and mode, read and checked when the study is read, and matched to
// the study's cases before anything is computed.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

struct ReferenceRow {
    nlohmann::json published;     // the row as published
    std::string json_path;        // "/rows/<i>" in the table's file
    std::string kernel;           // the kernel's name
    std::size_t kernel_index = 0; // into the study's kernels (resolve_reference_table)
    bool no_root = false;         // the paper finds no root in the interval
    double k = 0;
    std::optional<double> eps_rho, eps_gradp; // empty where the paper prints no number
    std::optional<std::string> erratum, erratum_eps_rho, erratum_eps_gradp;
};

struct ReferenceTable {
    std::string file;
    nlohmann::json document;
    std::string lattice, volume_coefficient, mode;
    double tolerance = 1e-4;
    std::vector<ReferenceRow> rows;
    // Resolved: indices into the study's lattices, volume coefficients and modes.
    std::size_t lattice_index = 0, volume_coefficient_index = 0, mode_index = 0;
};

// Reads and checks the table; errors name its file and the JSON Pointer at fault.
ReferenceTable read_reference_table(const std::filesystem::path& file);

// The names the study's cases go by, in the study's order.
struct StudyCaseNames {
    std::vector<std::string> lattices, modes, volume_coefficients, kernels;
};

// Matches the table's lattice, volume coefficient, mode and each row's kernel to the study's;
// a row with no case is refused (its file and JSON Pointer).
void resolve_reference_table(ReferenceTable& table, const StudyCaseNames& names);

} // namespace sphkern
