// The one error type every fallible operation throws: a one-line message and the
// documented exit code the command line turns it into.
#pragma once

#include <stdexcept>
#include <string>

namespace sphkern {

enum class ExitCode : int {
    ok = 0,
    check_failed = 1,  // `check`: a kernel check failed (or warned, with --strict)
    usage = 2,         // bad command-line arguments
    input = 3,         // a bad input file, value or name (lattice, study, a_p, k, ...)
    plugin = 4,        // a plugin that cannot be loaded, validated or run
    output = 5,        // results could not be written, or the output exists
    interrupted = 130, // SIGINT or SIGTERM arrived; nothing was written
};

// An error is one line, whatever a file name or a JSON key holds: control characters escaped.
inline std::string one_line(const std::string& message)
{
    static const char hex[] = "0123456789abcdef";
    std::string line;
    for (unsigned char c : message) {
        if (c == '\n') line += "\\n";
        else if (c == '\r') line += "\\r";
        else if (c == '\t') line += "\\t";
        else if (c < 0x20 || c == 0x7f) line += std::string("\\x") + hex[c >> 4] + hex[c & 15];
        else line += static_cast<char>(c);
    }
    return line;
}

// What an input error is about, where a front end tells them apart (Python's exception
// classes): a name that names nothing, a file that is not there, or anything else.
enum class ErrorKind { general, unknown_name, missing_file };

class Error : public std::runtime_error {
public:
    // One line from the start: what() is a C string, which a NUL in a file's text would cut.
    Error(ExitCode code, const std::string& message, ErrorKind kind = ErrorKind::general)
        : std::runtime_error(one_line(message)), code_(code), kind_(kind)
    {}
    ExitCode code() const { return code_; }
    ErrorKind kind() const { return kind_; }

private:
    ExitCode code_;
    ErrorKind kind_;
};

[[noreturn]] inline void fail_input(const std::string& message) { throw Error(ExitCode::input, message); }
// An input that names nothing known (a kernel, a lattice, a study), and a file that is not there.
[[noreturn]] inline void fail_unknown(const std::string& message)
{
    throw Error(ExitCode::input, message, ErrorKind::unknown_name);
}
[[noreturn]] inline void fail_missing(const std::string& message)
{
    throw Error(ExitCode::input, message, ErrorKind::missing_file);
}
// A value outside its range, named as the command line gives it (exit 2). at_source
// (support/text/value_checks.hpp) makes it an input error (exit 3) when the value came from a file.
[[noreturn]] inline void fail_usage(const std::string& message) { throw Error(ExitCode::usage, message); }

} // namespace sphkern
