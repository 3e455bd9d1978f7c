#include "requests/kernels_request.hpp"

#include "kernels/kernel_json.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sphkern {

nlohmann::json kernels_listing(KernelRegistry& registry)
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : registry.plugins()) list.push_back(kernel_json(*p));
    return list;
}

void print_kernels(KernelRegistry& registry)
{
    fmt::print(results_file(), "{:<20} {:>4} {:<6} {:<12} {}\n", "name", "R", "dims", "parameters", "reference / file");
    for (const auto& p : registry.plugins()) {
        std::string params;
        for (const auto& q : p->parameters) params += (params.empty() ? "" : ",") + q.name;
        fmt::print(results_file(), "{:<20} {:>4g} {:<6} {:<12} {}\n{:<46} {}\n", p->name, p->support,
                   p->dimensions_text(), params.empty() ? "-" : params, p->reference, "", p->source);
    }
}

} // namespace sphkern
