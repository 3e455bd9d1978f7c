// The Fortran unformatted records of a Phantom dump: each record framed by its length in bytes,
// a 4-byte integer before and after it, in the byte order of the machine that wrote it. The first
// record holds Phantom's magic numbers (dump_utils' open_dumpfile_w), which tell a dump from
// other files and give the byte order. share/docs/particle-formats.md describes the layout.
// The reader (phantom_dump.cpp) and the writer (phantom_dump_writer.cpp) share what is here.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace sphkern {

// Phantom's dump_utils (utils_dumpfiles.f90): its magic numbers, sizes and data types.
namespace phantom {

// int1, int2, int1o, int2o: the first record's integers, new and old; iversion, the format.
constexpr std::int32_t magic = 60769, magic_real = 60878, magic_old = 690706, magic_real_old = 780806;
constexpr std::int32_t format_version = 1;
constexpr std::size_t lentag = 16, lenid = 100;
// The data types, in the order every header and every block holds them (counted from 0 here,
// from 1 in dump_utils).
constexpr int ntypes = 8, i_int = 0, i_int1 = 1, i_int4 = 3, i_int8 = 4, i_real = 5, i_real4 = 6, i_real8 = 7;
constexpr const char* type_names[ntypes] = {"integer", "int*1", "int*2", "int*4", "int*8", "real", "real*4", "real*8"};
constexpr int igas = 1;             // part's igas: itype 1
constexpr int max_arraylengths = 4; // hydro, sinks, (unused), MHD

inline bool is_real(int type) { return type >= i_real; }

// A value's bytes: "real" is the dump's default real (8, or 4 in small dumps and single-precision
// builds), "integer" Phantom's default (4).
inline std::size_t width(int type, std::size_t real_width)
{
    constexpr std::size_t widths[ntypes] = {4, 1, 2, 4, 8, 0, 4, 8};
    return type == i_real ? real_width : widths[type];
}

// A tag or the file id as stored: blank-padded to n characters (Fortran's character(len=n)).
inline std::string padded(const std::string& text, std::size_t n)
{
    std::string out = text.substr(0, n);
    out.resize(n, ' ');
    return out;
}

// And back: without the padding (blanks or NULs) either side.
inline std::string tag_of(const char* p, std::size_t n)
{
    std::string tag(p, n);
    while (!tag.empty() && (tag.back() == ' ' || tag.back() == '\0')) tag.pop_back();
    tag.erase(0, std::min(tag.find_first_not_of(' '), tag.size()));
    return tag;
}

} // namespace phantom

// Whether `file` begins as a Phantom (or sphNG) dump does: a first record of 20 or 24 bytes
// opening with the magic number 060769 (or the older 690706), in either byte order.
bool is_phantom_dump(const std::filesystem::path& file);

struct PhantomRecord {
    std::uint64_t offset = 0; // of its first byte of data
    std::uint32_t bytes = 0;
    std::size_t number = 0; // counted from 1
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

// Records written as a Fortran unformatted write makes them, in this machine's byte order (as
// Phantom writes): the length, the bytes, the length again.
class PhantomRecordWriter {
public:
    PhantomRecordWriter(std::ostream& out, std::string name) : out_(out), name_(std::move(name)) {}
    // Error(input) naming the file for a record of 2 GiB or more, which gfortran would split
    // into subrecords that PhantomRecords refuses.
    void record(const void* data, std::size_t bytes);
    void record(const std::string& text) { record(text.data(), text.size()); }
    template <class T>
    void record(const std::vector<T>& values)
    {
        record(values.data(), values.size() * sizeof(T));
    }

private:
    std::ostream& out_;
    std::string name_;
};

} // namespace sphkern
