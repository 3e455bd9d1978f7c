// Runs untrusted code (a plugin's functions) in a child process with a time bound,
// so that a crash or an endless loop becomes an error message instead of our death.
#pragma once

#include <functional>
#include <string>
#include <variant>

namespace sphkern {

struct IsolatedFailure {
    std::string reason; // e.g. "crashed with signal 11 (Segmentation fault)"
};

// Calls `work` in a forked child and returns the string it produced, or why it failed.
// An exception escaping `work` is reported as a failure with its message.
std::variant<std::string, IsolatedFailure> run_isolated(const std::function<std::string()>& work,
                                                        double timeout_seconds);

} // namespace sphkern
