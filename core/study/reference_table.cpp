#include "study/reference_table.hpp"

#include "support/error.hpp"
#include "support/io/json_input.hpp"

#include <algorithm>

namespace sphkern {

namespace {

std::optional<std::string> optional_text(const JsonNode& row, const char* key)
{
    if (auto v = row.find(key)) return v->string();
    return std::nullopt;
}

ReferenceRow read_row(const JsonNode& row)
{
    row.expect_keys({"kernel", "k", "eps_rho", "eps_gradp", "printed_eps_gradp", "no_root", "erratum",
                     "erratum_eps_gradp", "erratum_eps_rho"});
    ReferenceRow r;
    r.published = row.value();
    r.json_path = row.path();
    r.kernel = row.at("kernel").string();
    optional_text(row, "printed_eps_gradp");
    r.erratum = optional_text(row, "erratum");
    r.erratum_eps_gradp = optional_text(row, "erratum_eps_gradp");
    r.erratum_eps_rho = optional_text(row, "erratum_eps_rho");
    if (auto no_root = row.find("no_root"); no_root && no_root->boolean()) {
        r.no_root = true;
        return r;
    }
    r.k = row.at("k").number();
    // A number, or null where the paper prints none.
    if (auto v = row.at("eps_rho"); !v.value().is_null()) r.eps_rho = v.number();
    if (auto v = row.at("eps_gradp"); !v.value().is_null()) r.eps_gradp = v.number();
    return r;
}

// The index of `name` in `names`, if it is there.
std::optional<std::size_t> index_of(const std::vector<std::string>& names, const std::string& name)
{
    auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) return std::nullopt;
    return static_cast<std::size_t>(it - names.begin());
}

} // namespace

ReferenceTable read_reference_table(const std::filesystem::path& file)
{
    ReferenceTable table;
    table.file = file.string();
    table.document = read_json_file(file);
    JsonNode root(table.document, table.file);
    root.expect_keys({"source", "lattice", "volume_coefficient", "mode", "tolerance", "rows"});
    table.lattice = root.at("lattice").string();
    table.volume_coefficient = root.at("volume_coefficient").string();
    table.mode = root.at("mode").string();
    table.tolerance = root.find("tolerance") ? root.at("tolerance").number_in(0, 1) : 1e-4;
    auto rows = root.at("rows");
    rows.expect_array(1);
    for (std::size_t i = 0; i < rows.size(); ++i) table.rows.push_back(read_row(rows[i]));
    return table;
}

void resolve_reference_table(ReferenceTable& table, const StudyCaseNames& names)
{
    const auto lattice = index_of(names.lattices, table.lattice), mode = index_of(names.modes, table.mode),
               ap = index_of(names.volume_coefficients, table.volume_coefficient);
    for (auto& row : table.rows) {
        const auto kernel = index_of(names.kernels, row.kernel);
        if (!lattice || !mode || !ap || !kernel)
            fail_input(table.file + ": " + row.json_path + ": the study has no case " + row.kernel + " / " +
                       table.lattice + " / " + table.volume_coefficient + " / mode " + table.mode);
        row.kernel_index = *kernel;
    }
    table.lattice_index = lattice.value_or(0);
    table.mode_index = mode.value_or(0);
    table.volume_coefficient_index = ap.value_or(0);
}

} // namespace sphkern
