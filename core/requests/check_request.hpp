// One check request (the command line's `check`): the kernel author's check-up of named
// kernels, the kernels of plugin files, or every kernel found, each in a child process.
#pragma once

#include "kernels/check_status.hpp"
#include "kernels/kernel.hpp"
#include "kernels/kernel_registry.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sphkern {

struct CheckRequest {
    std::vector<std::string> names;             // kernels by name or file
    std::vector<std::filesystem::path> plugins; // loaded too; alone (no names, not all): only theirs
    std::map<std::string, double> parameters;   // for every kernel checked
    bool all = false;                           // every kernel found
    bool strict = false;                        // a warning fails too
    double timeout = 60;                        // seconds per kernel
};

// How the front end names each value in its errors.
struct CheckSources {
    ValueSource timeout;
    std::string choices; // how to name something to check: "name a kernel, give --plugin FILE, or use --all"
};
CheckSources check_sources(FrontEnd front_end);

// Nothing to check (Error(usage)), or a timeout outside [0.1, 3600] s (named by its source).
void check_check_request(const CheckRequest& request, const CheckSources& sources);

// Where the kernels come from: only the plugin files, or every kernel found and them. The
// caller keeps it while the kernels live.
KernelRegistry check_registry(const CheckRequest& request);
// The kernels to check, in the order they are reported.
std::vector<Kernel> kernels_to_check(const CheckRequest& request, KernelRegistry& registry);

struct KernelCheck {
    const Kernel* kernel = nullptr;
    CheckStatus verdict = CheckStatus::ok;
    nlohmann::json document; // check_kernel's
};

// One kernel, in a child process bounded by the request's timeout.
KernelCheck run_check(const CheckRequest& request, const Kernel& kernel);

// Whether a check fails the request: a failure, or with `strict` a warning.
bool check_fails(const KernelCheck& check, bool strict);

// The text `sphkern check` prints for one kernel, on the results file.
void print_check(const KernelCheck& check);

} // namespace sphkern
