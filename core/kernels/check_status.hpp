// The status of one kernel check and the verdict over all of them, worst last: text only
// in documents (the check runs in a child process and sends its result as JSON).
#pragma once

#include <string_view>

namespace sphkern {

enum class CheckStatus { ok, warn, fail };

const char* check_status_name(CheckStatus status); // "ok", "warn", "fail"
// The status a document names; Error(plugin) for any other text.
CheckStatus check_status_named(std::string_view name);

} // namespace sphkern
