// Errors in a study's inputs name the study file and the JSON Pointer of the entry at
// fault: "file: /pointer: what is wrong, what was expected" (support/text/value_checks.hpp's
// ValueSource::json).
#pragma once

#include "support/text/value_checks.hpp"

#include <string>
#include <utility>

namespace sphkern {

// Runs `f`; an Error it throws is thrown again with "file: pointer: " before its message,
// its exit code kept.
template <class F>
decltype(auto) at_study_path(const std::string& file, const std::string& pointer, F&& f)
{
    return at_source(ValueSource::json(file, pointer), std::forward<F>(f));
}

} // namespace sphkern
