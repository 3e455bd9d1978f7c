// The Fortran unformatted records of a GADGET binary snapshot: each record framed by its length
// in bytes, before and after it, in the byte order of the machine that wrote it. SnapFormat 1
// begins with the 256-byte header; SnapFormat 2 puts before every block an 8-byte record naming
// it ("HEAD", "POS ", ...). share/docs/particle-formats.md describes the layout.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// Whether `file` begins as a GADGET binary snapshot does (its first marker 256, or 8 before a
// four-letter label), in either byte order.
bool is_gadget_binary(const std::filesystem::path& file);

struct GadgetRecord {
    std::uint64_t offset = 0; // of its first byte of data
    std::uint32_t bytes = 0;
    std::size_t number = 0; // counted from 1 among all the file's records, labels included
    std::string label;      // SnapFormat 2: the block's name, its trailing blanks dropped; else ""
};

class GadgetRecords {
public:
    // Walks every record of the file, checking that each one's two markers agree and that the
    // file holds them whole. Throws Error(input) naming the file and the record at fault.
    explicit GadgetRecords(const std::filesystem::path& file);

    const std::string& name() const { return name_; }
    int format() const { return format_; } // GADGET's SnapFormat: 1 or 2
    // The records of data in file order, the header first; SnapFormat 2's labels are their names.
    const std::vector<GadgetRecord>& blocks() const { return blocks_; }

    // A record's bytes as stored. Each read opens the file anew: a snapshot of many parts holds
    // none of them open.
    std::vector<char> bytes(const GadgetRecord& record) const;
    // `count` floating-point values of `width` bytes (4 or 8) from value `first` on, as doubles.
    std::vector<double> reals(const GadgetRecord& record, std::size_t first, std::size_t count,
                              std::size_t width) const;
    // A 4-byte integer at `at` in the header's bytes, in the file's byte order.
    std::uint32_t word(const std::vector<char>& bytes, std::size_t at) const;
    double real(const std::vector<char>& bytes, std::size_t at) const;

private:
    std::string name_;
    bool swapped_ = false;
    int format_ = 1;
    std::filesystem::path path_;
    std::vector<GadgetRecord> blocks_;
};

} // namespace sphkern
