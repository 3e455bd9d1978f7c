#include "kernels/kernel_json.hpp"

#include <nlohmann/json.hpp>

namespace sphkern {

nlohmann::json kernel_json(const KernelDefinition& p)
{
    nlohmann::json parameters = nlohmann::json::array();
    for (const auto& q : p.parameters)
        parameters.push_back({{"name", q.name},
                              {"description", q.description},
                              {"default", q.default_value},
                              {"min", q.min_value},
                              {"max", q.max_value}});
    return {{"name", p.name},
            {"title", p.title},
            {"support", p.support},
            {"dimensions", p.dimensions},
            {"parameters", parameters},
            {"breakpoints", p.breakpoints},
            {"separate_derivative", p.separate_derivative},
            {"reference", p.reference},
            {"file", p.source}};
}

} // namespace sphkern
