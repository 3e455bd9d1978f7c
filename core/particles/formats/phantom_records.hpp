// The Fortran unformatted records of a Phantom dump: each record framed by its length in bytes,
// a 4-byte integer before and after it, in the byte order of the machine that wrote it. The first
// record holds Phantom's magic numbers (dump_utils' open_dumpfile_w), which tell a dump from
// other files and give the byte order. share/docs/particle-formats.md describes the layout.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// Whether `file` begins as a Phantom (or sphNG) dump does: a first record of 20 or 24 bytes
// opening with the magic number 060769 (or the older 690706), in either byte order.
bool is_phantom_dump(const std::filesystem::path& file);

struct PhantomRecord {
    std::uint64_t offset = 0; // of its first byte of data
    std::uint32_t bytes = 0;
    std::size_t number = 0;   // counted from 1
};

class PhantomRecords {
public:
    // Walks every record of the file, checking that each one's two markers agree and that the
    // file holds them whole. Throws Error(input) naming the file and the record at fault.
    explicit PhantomRecords(const std::filesystem::path& file);

    const std::string& name() const { return name_; }
    bool swapped() const { return swapped_; }
    const std::vector<PhantomRecord>& records() const { return records_; }

    // A record's bytes as stored.
    std::vector<char> bytes(const PhantomRecord& record) const;
    // An integer or a floating-point value of `width` bytes at `p`, in the file's byte order.
    std::int64_t integer(const char* p, std::size_t width) const;
    double real(const char* p, std::size_t width) const;

private:
    std::string name_;
    bool swapped_ = false;
    std::filesystem::path path_;
    std::vector<PhantomRecord> records_;
};

} // namespace sphkern
