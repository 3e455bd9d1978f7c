// The headers that most units of every layer include, compiled once for all of them
// (core/CMakeLists.txt: target_precompile_headers). No header of ours: editing one must
// not rebuild everything. What each costs, and where it may be included: internals.md, "Build time".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>
