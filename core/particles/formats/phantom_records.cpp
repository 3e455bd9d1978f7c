#include "particles/formats/phantom_records.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <optional>

namespace sphkern {

namespace {

std::uint32_t phantom_word(const char* p, bool swapped)
{
    std::uint32_t v = 0;
    std::memcpy(&v, p, sizeof v);
    return swapped ? __builtin_bswap32(v) : v;
}

bool phantom_first_record(std::uint32_t bytes) { return bytes == 20 || bytes == 24; }

// The byte order in which the first 8 bytes read as a first record's marker and magic number.
std::optional<bool> phantom_order(const char* head)
{
    for (const bool swapped : {false, true}) {
        const std::uint32_t magic = phantom_word(head + 4, swapped);
        if (phantom_first_record(phantom_word(head, swapped)) &&
            (magic == static_cast<std::uint32_t>(phantom::magic) ||
             magic == static_cast<std::uint32_t>(phantom::magic_old)))
            return swapped;
    }
    return std::nullopt;
}

} // namespace

bool is_phantom_dump(const std::filesystem::path& file)
{
    char head[8] = {};
    std::ifstream in(file, std::ios::binary);
    in.read(head, sizeof head);
    return in.gcount() == sizeof head && phantom_order(head).has_value();
}

PhantomRecords::PhantomRecords(const std::filesystem::path& file) : name_(file.string()), path_(file)
{
    std::ifstream in(file, std::ios::binary);
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(file, ec);
    if (!in || ec) fail_input(name_ + ": cannot be opened for reading");
    char head[8] = {};
    in.read(head, sizeof head);
    const auto order = phantom_order(head);
    if (!in || !order)
        fail_input(fmt::format("{}: its first record is not Phantom's magic numbers; expected a 20- or 24-byte record "
                               "opening with {}",
                               name_, phantom::magic));
    swapped_ = *order;
    char marker[4];
    auto read_marker = [&](std::uint64_t at) {
        in.seekg(static_cast<std::streamoff>(at));
        in.read(marker, sizeof marker);
        if (!in) fail_input(fmt::format("{}: the marker at byte {} cannot be read", name_, at));
        return phantom_word(marker, swapped_);
    };
    std::size_t number = 0;
    for (std::uint64_t at = 0; at < size;) {
        ++number;
        if (size - at < 4)
            fail_input(fmt::format("{}: record {}'s start marker is cut off after {} bytes (a truncated file?)", name_,
                                   number, size - at));
        const std::uint32_t bytes = read_marker(at);
        // gfortran splits a record over 2 GiB into subrecords, marked by a negative length.
        if (bytes >= 0x80000000u)
            fail_input(fmt::format("{}: record {} is over 2 GiB (gfortran's subrecords, a negative marker); expected "
                                   "records under 2 GiB",
                                   name_, number));
        if (size - at - 4 < std::uint64_t{bytes} + 4)
            fail_input(
                fmt::format("{}: record {} declares {} bytes, but the file ends {} bytes into it with no end marker "
                            "(a truncated file?)",
                            name_, number, bytes, size - at - 4));
        const std::uint32_t end = read_marker(at + 4 + bytes);
        if (end != bytes)
            fail_input(
                fmt::format("{}: record {}'s end marker is {}, its start marker {} (a truncated or corrupt file?)",
                            name_, number, end, bytes));
        records_.push_back({at + 4, bytes, number});
        at += std::uint64_t{bytes} + 8;
    }
}

std::vector<char> PhantomRecords::bytes(const PhantomRecord& record) const
{
    std::vector<char> data(record.bytes);
    std::ifstream in(path_, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(record.offset));
    in.read(data.data(), static_cast<std::streamsize>(data.size()));
    if (!in) fail_input(fmt::format("{}: record {} cannot be read", name_, record.number));
    return data;
}

std::int64_t PhantomRecords::integer(const char* p, std::size_t width) const
{
    std::uint64_t v = 0;
    std::memcpy(&v, p, width);
    if (swapped_) v = __builtin_bswap64(v) >> (64 - 8 * width);
    // Sign-extend from `width` bytes: Fortran's integers are signed.
    const unsigned shift = static_cast<unsigned>(64 - 8 * width);
    return static_cast<std::int64_t>(v << shift) >> shift;
}

double PhantomRecords::real(const char* p, std::size_t width) const
{
    if (width == 4) return std::bit_cast<float>(phantom_word(p, swapped_));
    std::uint64_t v = 0;
    std::memcpy(&v, p, sizeof v);
    return std::bit_cast<double>(swapped_ ? __builtin_bswap64(v) : v);
}

void PhantomRecordWriter::record(const void* data, std::size_t bytes)
{
    if (bytes >= 0x80000000u)
        fail_input(fmt::format("{}: a record of {} bytes; a Phantom dump's records are under 2 GiB (gfortran splits "
                               "larger ones into subrecords); expected fewer particles",
                               name_, bytes));
    const auto marker = static_cast<std::uint32_t>(bytes);
    out_.write(reinterpret_cast<const char*>(&marker), sizeof marker);
    out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
    out_.write(reinterpret_cast<const char*>(&marker), sizeof marker);
}

} // namespace sphkern
