// Reading JSON input files with errors that name the file, the JSON Pointer path,
// what is wrong and what was expected.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sphkern {

// Reads and parses a JSON file: refuses missing paths, folders, unreadable or empty
// files, files over the size limit, nesting deeper than the depth limit and bytes
// that are not UTF-8, each with one line naming the file.
nlohmann::json read_json_file(const std::filesystem::path& file);

// Reads a whole input file of any type (a pipe, a device) but never more than `limit`
// bytes: refuses missing paths and folders; `what` names the expected content in errors.
std::string read_input_file(const std::filesystem::path& file, std::size_t limit, const std::string& what);

// "~" and "/" escaped as JSON Pointer (RFC 6901) tokens need.
std::string escape_json_pointer(std::string_view token);

// The same checks on text already in memory (and no key twice in one object); `name` stands for the file in errors.
nlohmann::json parse_json_text(const std::string& text, const std::string& name);

inline constexpr std::size_t max_json_bytes = 16u << 20;
inline constexpr int max_json_depth = 64;

// A value inside a parsed document, with the file and path needed for errors.
class JsonNode {
public:
    JsonNode(const nlohmann::json& value, std::string file, std::string path = "")
        : value_(&value), file_(std::move(file)), path_(std::move(path))
    {}

    const nlohmann::json& value() const { return *value_; }
    const std::string& file() const { return file_; }
    std::string path() const { return path_.empty() ? "/" : path_; }

    [[noreturn]] void error(const std::string& what) const;

    JsonNode at(std::string_view key) const;                  // required member of an object
    std::optional<JsonNode> find(std::string_view key) const; // optional member
    JsonNode operator[](std::size_t index) const;             // element of an array
    std::size_t size() const { return value_->size(); }

    // Refuses members not in `known`, suggesting the closest known key.
    void expect_keys(std::initializer_list<std::string_view> known) const;
    void expect_keys(const std::vector<std::string>& known) const;

    void expect_object() const;
    std::size_t expect_array(std::size_t min_size, std::size_t max_size = 100000) const;
    double number() const; // finite number
    double number_in(double lo, double hi) const;
    long long integer_in(long long lo, long long hi) const;
    std::string string() const; // non-empty string
    std::string text() const;   // any string, empty too
    bool boolean() const;
    bool is_string() const { return value_->is_string(); }
    bool is_number() const { return value_->is_number(); }
    bool is_object() const { return value_->is_object(); }
    bool is_array() const { return value_->is_array(); }
    bool is_boolean() const { return value_->is_boolean(); }

private:
    const nlohmann::json* value_;
    std::string file_;
    std::string path_;
};

std::string json_type_name(const nlohmann::json& value);

} // namespace sphkern
