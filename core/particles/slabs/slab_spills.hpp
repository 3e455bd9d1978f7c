// Records per slab of a set measured slab by slab, each slab's in a file of its own in a folder
// sphkern makes in the temporary directory: the particles each slab reads (its own and its
// halo's, in file order), and the per-particle results of its own particles (their file rows
// and values, in file order), read back merged into file order, run by run. The folder is
// removed when the spills go, and by a second interrupting signal (a staging path).
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace sphkern {

class SlabSpills {
public:
    // `fields` values a record, the first the particle's file row. Throws Error(output) where
    // the folder cannot be made.
    SlabSpills(std::size_t fields, std::size_t slabs);
    ~SlabSpills();
    SlabSpills(const SlabSpills&) = delete;
    SlabSpills& operator=(const SlabSpills&) = delete;

    // The folder's file system: where the records need room.
    static std::filesystem::path folder_parent();

    // Appends whole records to slab s's file (each slab's rows rising, slab after slab).
    void append(std::size_t slab, std::span<const double> records);
    void close_slab(std::size_t slab);

    // The rows [0, n) in file order, in runs of `run` rows: visit(begin, count, columns), with
    // columns[f][k] field f of row begin + k (every row in exactly one slab). The slabs' files
    // are read into a run's columns on `threads` threads, each slab's on one.
    using Visit =
        std::function<void(std::size_t begin, std::size_t count, const std::vector<std::vector<double>>& columns)>;
    void merge(std::size_t n, std::size_t run, int threads, const Visit& visit) const;

    // Slab s's records in the order appended: visit(record) for each.
    void read(std::size_t slab, const std::function<void(const double* record)>& visit) const;

private:
    std::size_t fields_;
    std::filesystem::path folder_;
    std::vector<std::filesystem::path> files_;
    std::vector<std::FILE*> open_;
};

} // namespace sphkern
