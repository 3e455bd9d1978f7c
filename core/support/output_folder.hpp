// An output folder that appears complete or not at all: files are written into a
// temporary sibling folder, which is renamed into place on commit.
#pragma once

#include <filesystem>

namespace sphkern {

class OutputFolder {
public:
    // Throws Error(output) if `target` exists and `overwrite` is false, or if the
    // temporary folder cannot be made.
    OutputFolder(std::filesystem::path target, bool overwrite);
    ~OutputFolder(); // removes the temporary folder unless committed

    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    const std::filesystem::path& staging() const { return staging_; }
    void write(const std::string& name, const std::string& content);
    void commit(); // replaces `target` with the staged folder

private:
    std::filesystem::path target_;
    std::filesystem::path staging_;
    bool overwrite_;
    bool committed_ = false;
};

} // namespace sphkern
