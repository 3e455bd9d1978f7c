// A SWIFT or GADGET snapshot (/Header, /PartType0), in one file or in the NumFilesPerSnapshot
// parts BASE.0.hdf5 ... of SWIFT's distributed snapshots and GADGET's multi-part files, read a
// run of rows at a time: a set read whole is its rows [0, N), and a set larger than memory is
// read in slabs (particles/slabs) without ever holding it.
#pragma once

#include "particles/particle_set.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sphkern {

class SnapshotRows {
public:
    // Opens the snapshot, or all its parts from any one of them, and checks what their headers
    // declare (the parts' headers alike, every part there, the counts adding up). Throws
    // Error(input) naming the file or the part at fault.
    explicit SnapshotRows(const std::filesystem::path& file);
    ~SnapshotRows();
    SnapshotRows(const SnapshotRows&) = delete;
    SnapshotRows& operator=(const SnapshotRows&) = delete;

    std::size_t size() const;  // the particles of all parts
    std::size_t parts() const; // 1 for a snapshot in one file
    // The set's header and its first rows (at most two): what a request is checked against.
    // Its linked_files are every file the snapshot reads (its parts and their links).
    const ParticleSet& sample() const;
    // Rows [begin, end) in file order, ParticleSet::ids their rows where begin > 0; as stored
    // (not yet validated).
    ParticleSet rows(std::size_t begin, std::size_t end) const;
    // A periodic box for the set, in place of the file's (or where it has none).
    void set_box(const PeriodicBox& box);

private:
    struct Parts;
    std::unique_ptr<Parts> parts_;
};

// Whether `file` is a SWIFT or GADGET snapshot (it has /PartType0); false for other files.
bool is_snapshot(const std::filesystem::path& file);

} // namespace sphkern
