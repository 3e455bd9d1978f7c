#include "requests/check_request.hpp"

#include "kernels/kernel_check.hpp"
#include "support/error.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace sphkern {

namespace {

bool only_files(const CheckRequest& r) { return r.names.empty() && !r.all; }

} // namespace

CheckSources check_sources(FrontEnd f)
{
    return {value_named(f, "timeout"), f == FrontEnd::command_line
                                           ? "name a kernel, give --plugin FILE, or use --all"
                                           : "name a kernel, give plugin=FILE, or use all=True"};
}

void check_check_request(const CheckRequest& r, const CheckSources& sources)
{
    if (only_files(r) && r.plugins.empty()) throw Error(sources.timeout.code, "check: " + sources.choices);
    check_range(r.timeout, 0.1, 3600, sources.timeout);
}

KernelRegistry check_registry(const CheckRequest& r)
{
    return only_files(r) ? KernelRegistry::from_files(r.plugins) : KernelRegistry::discover(r.plugins);
}

std::vector<Kernel> kernels_to_check(const CheckRequest& r, KernelRegistry& registry)
{
    std::vector<Kernel> kernels;
    if (r.all || only_files(r))
        for (const auto& p : registry.plugins()) kernels.emplace_back(p, r.parameters);
    for (const auto& name : r.names) kernels.emplace_back(registry.find(name), r.parameters);
    return kernels;
}

KernelCheck run_check(const CheckRequest& r, const Kernel& kernel)
{
    auto document = check_kernel_isolated(kernel, r.timeout);
    const auto verdict = check_status_named(document["verdict"].get<std::string>());
    return {&kernel, verdict, std::move(document)};
}

bool check_fails(const KernelCheck& check, bool strict)
{
    return check.verdict == CheckStatus::fail || (strict && check.verdict == CheckStatus::warn);
}

void print_check(const KernelCheck& check)
{
    const auto& d = check.document;
    fmt::print(results_file(), "{} ({}): {}\n", check.kernel->label(), check.kernel->definition().source,
               check_status_name(check.verdict));
    // Each column as wide as its longest entry, so that every row's columns start alike (the
    // status at least as wide as "warn" and "fail", the same for a kernel whose checks are all ok).
    std::size_t name_width = 0, status_width = 4;
    for (const auto& c : d["checks"]) {
        name_width = std::max(name_width, c["check"].get<std::string>().size());
        status_width = std::max(status_width, c["status"].get<std::string>().size());
    }
    for (const auto& c : d["checks"])
        fmt::print(results_file(), "  {}D {:<{}} {:<{}} {}\n", c["dimension"].get<int>(), c["check"].get<std::string>(),
                   name_width, c["status"].get<std::string>(), status_width, c["detail"].get<std::string>());
    for (const auto& c : d["checks"])
        if (c.contains("hint"))
            fmt::print(results_file(), "  hint ({}D {}): {}\n", c["dimension"].get<int>(),
                       c["check"].get<std::string>(), c["hint"].get<std::string>());
}

} // namespace sphkern
