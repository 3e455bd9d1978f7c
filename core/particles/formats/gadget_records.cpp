#include "particles/formats/gadget_records.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <optional>

namespace sphkern {

namespace {

constexpr std::uint32_t header_bytes = 256, label_bytes = 8;

std::uint32_t swap_if(std::uint32_t v, bool swapped) { return swapped ? __builtin_bswap32(v) : v; }

std::uint32_t load_word(const char* p, bool swapped)
{
    std::uint32_t v = 0;
    std::memcpy(&v, p, sizeof v);
    return swap_if(v, swapped);
}

double load_real(const char* p, std::size_t width, bool swapped)
{
    if (width == 4) return std::bit_cast<float>(load_word(p, swapped));
    std::uint64_t v = 0;
    std::memcpy(&v, p, sizeof v);
    return std::bit_cast<double>(swapped ? __builtin_bswap64(v) : v);
}

// The byte order of a file whose first marker is `first`: whichever reads it as 256 or 8.
std::optional<bool> swapped_for(std::uint32_t first)
{
    if (first == header_bytes || first == label_bytes) return false;
    const std::uint32_t other = __builtin_bswap32(first);
    if (other == header_bytes || other == label_bytes) return true;
    return std::nullopt;
}

std::string label_of(const char* p)
{
    std::string label(p, 4);
    while (!label.empty() && (label.back() == ' ' || label.back() == '\0')) label.pop_back();
    return label;
}

// One run of bytes from `file`, named `name` and its record in errors.
std::vector<char> read_span(const std::filesystem::path& file, const std::string& name, std::size_t record,
                            std::uint64_t at, std::size_t count)
{
    std::vector<char> data(count);
    std::ifstream in(file, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(at));
    in.read(data.data(), static_cast<std::streamsize>(count));
    if (!in) fail_input(fmt::format("{}: record {} cannot be read", name, record));
    return data;
}

} // namespace

bool is_gadget_binary(const std::filesystem::path& file)
{
    char head[8] = {};
    std::ifstream in(file, std::ios::binary);
    in.read(head, sizeof head);
    const auto got = in.gcount();
    if (got < 4) return false;
    const auto swapped = swapped_for(load_word(head, false));
    if (!swapped) return false;
    if (load_word(head, *swapped) == header_bytes) return true;
    // SnapFormat 2: the marker 8 is common in other files; its four printable letters are not.
    return got == 8 && std::all_of(head + 4, head + 8, [](char c) { return c >= 0x20 && c < 0x7f; });
}

namespace {

// The four bytes of a record marker at byte `at`.
void read_marker(std::ifstream& in, const std::string& name, std::uint64_t at, char (&marker)[4])
{
    in.seekg(static_cast<std::streamoff>(at));
    in.read(marker, sizeof marker);
    if (!in) fail_input(fmt::format("{}: the marker at byte {} cannot be read", name, at));
}

// The length of record `number` at byte `at` of a file of `size` bytes, from its start marker,
// checked against the file's end and its end marker.
std::uint32_t record_length(std::ifstream& in, const std::string& name, std::uint64_t at, std::uint64_t size,
                            std::size_t number, bool swapped)
{
    char marker[4];
    if (size - at < 4)
        fail_input(fmt::format("{}: record {}'s start marker is cut off after {} bytes (a truncated file?)", name,
                               number, size - at));
    read_marker(in, name, at, marker);
    const std::uint32_t bytes = load_word(marker, swapped);
    if (size - at - 4 < std::uint64_t{bytes} + 4)
        fail_input(fmt::format("{}: record {} declares {} bytes, but the file ends {} bytes into it with no end marker "
                               "(a truncated file?)",
                               name, number, bytes, size - at - 4));
    read_marker(in, name, at + 4 + bytes, marker);
    if (const std::uint32_t end = load_word(marker, swapped); end != bytes)
        fail_input(fmt::format("{}: record {}'s end marker is {}, its start marker {} (a truncated or corrupt file?)",
                               name, number, end, bytes));
    return bytes;
}

} // namespace

GadgetRecords::GadgetRecords(const std::filesystem::path& file) : name_(file.string()), path_(file)
{
    std::ifstream in(file, std::ios::binary);
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(file, ec);
    if (!in || ec) fail_input(name_ + ": cannot be opened for reading");
    char marker[4];
    if (size < 4) fail_input(fmt::format("{}: {} bytes; expected a GADGET binary snapshot's records", name_, size));
    read_marker(in, name_, 0, marker);
    const std::uint32_t first = load_word(marker, false);
    const auto swapped = swapped_for(first);
    if (!swapped)
        fail_input(
            fmt::format("{}: its first record marker is {}; expected 256 (GADGET SnapFormat 1) or 8 (SnapFormat 2), "
                        "in either byte order",
                        name_, first));
    swapped_ = *swapped;
    format_ = load_word(marker, swapped_) == header_bytes ? 1 : 2;
    std::string label;
    bool label_next = format_ == 2;
    std::size_t number = 0;
    for (std::uint64_t at = 0; at < size;) {
        const std::uint32_t bytes = record_length(in, name_, at, size, ++number, swapped_);
        if (label_next) {
            if (bytes != label_bytes)
                fail_input(
                    fmt::format("{}: record {} is {} bytes where SnapFormat 2 puts an 8-byte block label; expected "
                                "labels and blocks in turn",
                                name_, number, bytes));
            char text[4];
            in.seekg(static_cast<std::streamoff>(at + 4));
            in.read(text, sizeof text);
            label = label_of(text);
        } else {
            blocks_.push_back({at + 4, bytes, number, label});
        }
        if (format_ == 2) label_next = !label_next;
        at += std::uint64_t{bytes} + 8;
    }
    if (format_ == 2 && !label_next)
        fail_input(fmt::format("{}: record {}, the label of block {}, is the file's last; expected the block after it "
                               "(a truncated file?)",
                               name_, number, label));
}

std::vector<char> GadgetRecords::bytes(const GadgetRecord& record) const
{
    return read_span(path_, name_, record.number, record.offset, record.bytes);
}

std::vector<double> GadgetRecords::reals(const GadgetRecord& record, std::size_t first, std::size_t count,
                                         std::size_t width) const
{
    const auto data = read_span(path_, name_, record.number, record.offset + first * width, count * width);
    std::vector<double> values(count);
    for (std::size_t i = 0; i < count; ++i) values[i] = load_real(data.data() + i * width, width, swapped_);
    return values;
}

std::uint32_t GadgetRecords::word(const std::vector<char>& bytes, std::size_t at) const
{
    return load_word(bytes.data() + at, swapped_);
}

double GadgetRecords::real(const std::vector<char>& bytes, std::size_t at) const
{
    return load_real(bytes.data() + at, 8, swapped_);
}

} // namespace sphkern
