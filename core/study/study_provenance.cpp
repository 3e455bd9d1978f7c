#include "study/study_provenance.hpp"

#include "lattices/lattice_json.hpp"
#include "support/io/json_input.hpp"
#include "support/io/sha256.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace sphkern {

namespace {

bool is_file(const std::string& path)
{
    std::error_code ec;
    return !path.empty() && std::filesystem::is_regular_file(path, ec);
}

// The file as text when JSON can hold it (UTF-8), else null: the SHA-256 still identifies it.
nlohmann::json file_text(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
        nlohmann::json value = text.str();
        value.dump();
        return value;
    } catch (const nlohmann::json::exception&) {
        return nullptr;
    }
}

} // namespace

nlohmann::json kernel_input_json(const Kernel& kernel)
{
    const auto& d = kernel.definition();
    nlohmann::json parameters = nlohmann::json::object();
    for (std::size_t i = 0; i < d.parameters.size(); ++i)
        parameters[d.parameters[i].name] = kernel.parameter_values()[i];
    nlohmann::json entry = {{"label", kernel.label()}, {"name", d.name},          {"source", d.source}, {"abi", d.abi},
                            {"support", d.support},    {"parameters", parameters}};
    if (is_file(d.source)) {
        entry["file"] = d.source;
        entry["sha256"] = file_sha256_hex(d.source);
        if (d.from_expression) entry["expression"] = read_json_file(d.source);
    }
    return entry;
}

nlohmann::json lattice_input_json(const Lattice& lattice)
{
    nlohmann::json entry = {{"name", lattice.name}, {"file", lattice.file}};
    if (is_file(lattice.file)) {
        entry["sha256"] = file_sha256_hex(lattice.file);
        entry["definition"] = read_json_file(lattice.file);
    } else {
        entry["definition"] = lattice_json(lattice);
    }
    return entry;
}

nlohmann::json study_inputs_json(const Study& study, const StudyInputs& inputs)
{
    nlohmann::json study_entry = {{"file", study.file}};
    if (is_file(study.file)) {
        study_entry["sha256"] = file_sha256_hex(study.file);
        study_entry["text"] = file_text(study.file);
    }
    nlohmann::json kernels = nlohmann::json::array(), lattices = nlohmann::json::array();
    for (const auto& k : inputs.kernels) kernels.push_back(kernel_input_json(k));
    for (const auto& l : inputs.lattices) lattices.push_back(lattice_input_json(l));
    return {{"study", study_entry}, {"kernels", kernels}, {"lattices", lattices}};
}

} // namespace sphkern
