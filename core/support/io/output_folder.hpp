// An output folder that appears complete or not at all, and never destroys what
// sphkern did not write: files go into a staging sibling (marked as sphkern's), which
// is renamed into place without replacing anything, or, with overwrite, exchanged only
// with a folder that carries the same marker.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace sphkern {

class OutputFolder {
public:
    // The file inside every folder sphkern writes; --force replaces only such folders.
    static constexpr const char* marker_name = ".sphkern-output";

    // Throws Error(output) if `target` exists and `overwrite` is false, if it exists and
    // is not a folder sphkern wrote, or if the staging folder cannot be made.
    OutputFolder(const std::filesystem::path& target, bool overwrite);
    ~OutputFolder(); // removes the staging folder and the parents it created, unless committed

    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    const std::filesystem::path& target() const { return target_; }
    const std::filesystem::path& staging() const { return staging_; }
    void write(const std::string& name, const std::string& content);
    void write(const std::string& name, const std::function<void(std::ostream&)>& writer); // streamed
    void commit(); // moves the staged folder into place

private:
    void make_parents();
    void remove_created_parents();
    std::filesystem::path target_;
    std::filesystem::path staging_;
    std::vector<std::filesystem::path> created_parents_; // outermost first
    bool overwrite_;
    bool committed_ = false;
    bool keep_staging_ = false; // a folder sphkern did not write ended up at the staging path
};

// True if `folder` is a real folder (not a link) holding sphkern's marker file.
bool written_by_sphkern(const std::filesystem::path& folder);

} // namespace sphkern
