#include "support/io/json_input.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/text/printable_text.hpp"
#include "support/text/value_checks.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace sphkern {
namespace fs = std::filesystem;

namespace {

std::string strip_exception_prefix(const std::string& what)
{
    // nlohmann prefixes "[json.exception.parse_error.101] "; the prefix helps nobody.
    auto close = what.find("] ");
    return what.rfind("[json.exception", 0) == 0 && close != std::string::npos ? what.substr(close + 2) : what;
}

// Deepest bracket nesting outside strings; stops counting once past the limit.
int nesting_depth(const std::string& text)
{
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char c : text) {
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
            continue;
        }
        if (c == '"') in_string = true;
        else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (deepest > max_json_depth) break;
        } else if (c == ']' || c == '}') --depth;
    }
    return deepest;
}

} // namespace

std::string read_input_file(const fs::path& file, std::size_t limit, const std::string& what)
{
    const std::string name = file.string();
    // O_NONBLOCK: opening a FIFO without a writer must not hang; cleared again for reading.
    int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT || errno == ENOTDIR) fail_missing(name + ": no such file");
        fail_input(name + ": cannot be read (" + std::strerror(errno) + ")");
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) fail_input(name + ": cannot be read (" + std::strerror(errno) + ")");
    if (S_ISDIR(st.st_mode)) fail_input(name + ": is a folder, expected " + what);
    if (S_ISREG(st.st_mode) && static_cast<std::uintmax_t>(st.st_size) > limit)
        fail_input(name + ": file is " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                   std::to_string(limit) + " for " + what);
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    // Read at most limit + 1 bytes whatever the file is (a device or a pipe has no size).
    std::string text;
    char buffer[65536];
    for (;;) {
        throw_if_interrupted();
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail_input(name + ": cannot be read (" + std::strerror(errno) + ")");
        if (n == 0) break;
        text.append(buffer, static_cast<std::size_t>(n));
        if (text.size() > limit)
            fail_input(name + ": more than the limit of " + std::to_string(limit) + " bytes for " + what +
                       " (not a regular file?)");
    }
    return text;
}

nlohmann::json read_json_file(const fs::path& file)
{
    return parse_json_text(read_input_file(file, max_json_bytes, "a JSON input"), file.string());
}

std::string escape_json_pointer(std::string_view token)
{
    std::string escaped;
    for (char c : token) {
        if (c == '~') escaped += "~0";
        else if (c == '/') escaped += "~1";
        else escaped += c;
    }
    return escaped;
}

nlohmann::json parse_json_text(const std::string& text, const std::string& name)
{
    if (text.size() > max_json_bytes)
        fail_input(name + ": " + std::to_string(text.size()) + " bytes, more than the limit of " +
                   std::to_string(max_json_bytes) + " for a JSON input");
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) fail_input(name + ": file is empty, expected JSON");
    // JSON is text: a NUL byte (and whatever follows it) is not part of any document.
    if (const auto nul = text.find('\0'); nul != std::string::npos)
        fail_input(name + ": a NUL byte at offset " + std::to_string(nul) + "; expected JSON text");
    if (nesting_depth(text) > max_json_depth)
        fail_input(name + ": JSON nested deeper than " + std::to_string(max_json_depth) + " levels");
    // Refuses a key given twice in one object (nlohmann would keep the last silently).
    struct Frame {
        bool object;
        std::set<std::string> keys;
        std::string key;
        std::size_t index = 0;
    };
    std::vector<Frame> stack;
    auto path = [&] {
        std::string p;
        for (std::size_t i = 0; i + 1 < stack.size(); ++i) {
            p += '/';
            p += stack[i].object ? escape_json_pointer(stack[i].key) : std::to_string(stack[i].index);
        }
        return p.empty() ? std::string("/") : p;
    };
    auto element_done = [&] {
        if (!stack.empty() && !stack.back().object) ++stack.back().index;
    };
    using Event = nlohmann::json::parse_event_t;
    auto callback = [&](int, Event event, nlohmann::json& parsed) {
        switch (event) {
        case Event::object_start: stack.push_back({true, {}, {}}); break;
        case Event::array_start: stack.push_back({false, {}, {}}); break;
        case Event::object_end:
        case Event::array_end:
            stack.pop_back();
            element_done();
            break;
        case Event::key: {
            auto key = parsed.get<std::string>();
            stack.back().key = key;
            if (!stack.back().keys.insert(key).second) {
                stack.back().key.clear();
                fail_input(name + ": " + path() + ": duplicate key \"" + key + "\" (each key may appear once)");
            }
            break;
        }
        case Event::value: element_done(); break;
        }
        return true;
    };
    try {
        return nlohmann::json::parse(text, callback);
    } catch (const nlohmann::json::exception& e) {
        // The parser quotes the bytes it last read: the file's, so made printable like any file text.
        fail_input(name + ": not valid JSON: " + printable_text(strip_exception_prefix(e.what())));
    }
}

std::string json_type_name(const nlohmann::json& value)
{
    if (value.is_number()) return "a number";
    if (value.is_string()) return "a string";
    if (value.is_array()) return "an array";
    if (value.is_object()) return "an object";
    if (value.is_boolean()) return "a boolean";
    return "null";
}

void JsonNode::error(const std::string& what) const { fail_input(file_ + ": " + path() + ": " + what); }

void JsonNode::expect_object() const
{
    if (!value_->is_object()) error("expected an object, got " + json_type_name(*value_));
}

JsonNode JsonNode::at(std::string_view key) const
{
    auto found = find(key);
    if (!found) error("missing required key \"" + std::string(key) + "\"");
    return *found;
}

std::optional<JsonNode> JsonNode::find(std::string_view key) const
{
    expect_object();
    auto it = value_->find(key);
    if (it == value_->end()) return std::nullopt;
    return JsonNode(*it, file_, path_ + "/" + escape_json_pointer(key));
}

JsonNode JsonNode::operator[](std::size_t index) const
{
    return JsonNode((*value_)[index], file_, path_ + "/" + std::to_string(index));
}

void JsonNode::expect_keys(std::initializer_list<std::string_view> known) const
{
    expect_keys(std::vector<std::string>(known.begin(), known.end()));
}

void JsonNode::expect_keys(const std::vector<std::string>& names) const
{
    expect_object();
    for (const auto& [key, unused] : value_->items()) {
        if (std::find(names.begin(), names.end(), key) != names.end()) continue;
        std::string message = "unknown key \"" + key + "\"" + did_you_mean(key, names);
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        error(message + "; expected one of: " + list);
    }
}

std::size_t JsonNode::expect_array(std::size_t min_size, std::size_t max_size) const
{
    if (!value_->is_array()) error("expected an array, got " + json_type_name(*value_));
    if (value_->size() < min_size)
        error(value_->empty() ? "empty array, expected at least " + std::to_string(min_size) + " element(s)"
                              : "expected at least " + std::to_string(min_size) + " elements, got " +
                                    std::to_string(value_->size()));
    if (value_->size() > max_size)
        error("expected at most " + std::to_string(max_size) + " elements, got " + std::to_string(value_->size()));
    return value_->size();
}

double JsonNode::number() const
{
    if (!value_->is_number()) error("expected a number, got " + json_type_name(*value_));
    double v = value_->get<double>();
    if (!std::isfinite(v)) error("expected a finite number");
    return v;
}

double JsonNode::number_in(double lo, double hi) const
{
    double v = number();
    if (v < lo || v > hi) {
        std::ostringstream s;
        s << "value " << v << " is out of range, expected a number in [" << lo << ", " << hi << "]";
        error(s.str());
    }
    return v;
}

long long JsonNode::integer_in(long long lo, long long hi) const
{
    if (!value_->is_number_integer()) error("expected an integer, got " + json_type_name(*value_));
    long long v = value_->get<long long>();
    if (value_->is_number_unsigned() && value_->get<unsigned long long>() > static_cast<unsigned long long>(hi))
        v = hi + 1;
    if (v < lo || v > hi)
        error("value " + value_->dump() + " is out of range, expected an integer in [" + std::to_string(lo) + ", " +
              std::to_string(hi) + "]");
    return v;
}

std::string JsonNode::text() const
{
    if (!value_->is_string()) error("expected a string, got " + json_type_name(*value_));
    return value_->get<std::string>();
}

std::string JsonNode::string() const
{
    if (!value_->is_string()) error("expected a string, got " + json_type_name(*value_));
    auto s = value_->get<std::string>();
    if (s.empty()) error("expected a non-empty string");
    return s;
}

bool JsonNode::boolean() const
{
    if (!value_->is_boolean()) error("expected true or false, got " + json_type_name(*value_));
    return value_->get<bool>();
}

} // namespace sphkern
