// CLI11's parse errors in sphkern's words: an unknown command or option with the nearest one
// ("did you mean"), the extra words in the order they were typed, a value that is not a number
// with the form expected.
#pragma once

#include <string>

namespace CLI {
class App;
class ParseError;
} // namespace CLI

namespace sphkern::cli {

std::string usage_message(const CLI::App& app, const CLI::ParseError& error, int argc, const char* const* argv);

} // namespace sphkern::cli
