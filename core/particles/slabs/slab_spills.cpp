#include "particles/slabs/slab_spills.hpp"

#include "support/error.hpp"
#include "support/process/interruption.hpp"
#include "support/process/parallel_for.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace sphkern {

namespace {

// Records read back a buffer at a time, the next record always at hand.
class SpillReader {
public:
    SpillReader(const std::filesystem::path& file, std::size_t fields)
        : fields_(fields), file_(std::fopen(file.c_str(), "rb"))
    {
        if (!file_)
            throw Error(ExitCode::output,
                        fmt::format("{}: cannot be read back ({})", file.string(), std::strerror(errno)));
        buffer_.resize(fields * records_per_read);
        fill();
    }
    ~SpillReader() { std::fclose(file_); }
    SpillReader(const SpillReader&) = delete;
    SpillReader& operator=(const SpillReader&) = delete;
    bool done() const { return at_ >= end_; }
    std::size_t row() const { return static_cast<std::size_t>(buffer_[at_]); }
    const double* record() const { return buffer_.data() + at_; }
    void next()
    {
        at_ += fields_;
        if (at_ >= end_) fill();
    }

private:
    static constexpr std::size_t records_per_read = 1024;
    void fill()
    {
        const std::size_t records = std::fread(buffer_.data(), sizeof(double) * fields_, records_per_read, file_);
        at_ = 0, end_ = records * fields_;
    }
    std::size_t fields_;
    std::FILE* file_;
    std::vector<double> buffer_;
    std::size_t at_ = 0, end_ = 0;
};

} // namespace

std::filesystem::path SlabSpills::folder_parent()
{
    // TMPDIR as POSIX has it: unset or empty means /tmp; anything else must be a folder.
    const char* given = std::getenv("TMPDIR");
    if (!given || !*given) return "/tmp";
    std::error_code error;
    const auto status = std::filesystem::status(given, error);
    if (!std::filesystem::exists(status))
        throw Error(ExitCode::output,
                    fmt::format("TMPDIR={}: no such folder; expected a folder for the slabs' temporary "
                                "files (or TMPDIR unset, for /tmp)",
                                given));
    if (!std::filesystem::is_directory(status))
        throw Error(ExitCode::output, fmt::format("TMPDIR={}: not a folder; expected a folder for the slabs' temporary "
                                                  "files (or TMPDIR unset, for /tmp)",
                                                  given));
    return given;
}

SlabSpills::SlabSpills(std::size_t fields, std::size_t slabs) : fields_(fields)
{
    std::string pattern = (folder_parent() / "sphkern-slabs-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
        throw Error(ExitCode::output,
                    fmt::format("{}: cannot make a folder for the slabs' results ({})", pattern, std::strerror(errno)));
    folder_ = pattern;
    register_staging_path(folder_);
    for (std::size_t s = 0; s < slabs; ++s) {
        files_.push_back(folder_ / fmt::format("slab-{}.bin", s));
        open_.push_back(nullptr);
    }
}

SlabSpills::~SlabSpills()
{
    for (std::FILE* f : open_)
        if (f) std::fclose(f);
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec); // sphkern's own folder, made above
    unregister_staging_path(folder_);
}

void SlabSpills::append(std::size_t slab, std::span<const double> records)
{
    std::FILE*& f = open_[slab];
    if (!f && !(f = std::fopen(files_[slab].c_str(), "wb")))
        throw Error(ExitCode::output,
                    fmt::format("{}: cannot be written ({})", files_[slab].string(), std::strerror(errno)));
    if (std::fwrite(records.data(), sizeof(double), records.size(), f) != records.size())
        throw Error(ExitCode::output,
                    fmt::format("{}: the slabs' results cannot be written ({}); expected room in {}",
                                files_[slab].string(), std::strerror(errno), folder_parent().string()));
}

void SlabSpills::close_slab(std::size_t slab)
{
    std::FILE*& f = open_[slab];
    if (!f && !(f = std::fopen(files_[slab].c_str(), "wb")))
        throw Error(ExitCode::output,
                    fmt::format("{}: cannot be written ({})", files_[slab].string(), std::strerror(errno)));
    const bool written = std::fclose(f) == 0;
    f = nullptr;
    if (!written)
        throw Error(ExitCode::output, fmt::format("{}: the slabs' results cannot be written; expected room in {}",
                                                  files_[slab].string(), folder_parent().string()));
}

void SlabSpills::read(std::size_t slab, const std::function<void(const double* record)>& visit) const
{
    for (SpillReader reader(files_[slab], fields_); !reader.done(); reader.next()) visit(reader.record());
}

void SlabSpills::merge(std::size_t n, std::size_t run, int threads, const Visit& visit) const
{
    std::vector<std::unique_ptr<SpillReader>> readers;
    for (const auto& file : files_) readers.push_back(std::make_unique<SpillReader>(file, fields_));
    std::vector<std::vector<double>> columns(fields_, std::vector<double>(run));
    std::vector<std::size_t> placed(readers.size());
    for (std::size_t begin = 0; begin < n; begin += run) {
        throw_if_interrupted();
        const std::size_t count = std::min(run, n - begin), end = begin + count;
        // Each slab holds its own rows: the readers write disjoint places of the columns.
        ParallelFor pass;
        pass.run(readers.size(), threads, [&](int, std::size_t first, std::size_t last) {
            for (std::size_t s = first; s < last; ++s) {
                SpillReader& reader = *readers[s];
                for (placed[s] = 0; !reader.done() && reader.row() < end; reader.next(), ++placed[s]) {
                    const double* record = reader.record();
                    const std::size_t k = reader.row() - begin;
                    for (std::size_t f = 0; f < fields_; ++f) columns[f][k] = record[f];
                }
            }
        });
        std::size_t total = 0;
        for (const std::size_t p : placed) total += p;
        if (total != count) throw std::logic_error("the slabs' results miss rows");
        visit(begin, count, columns);
    }
}

} // namespace sphkern
