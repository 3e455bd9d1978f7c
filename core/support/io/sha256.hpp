// SHA-256 (FIPS 180-4) of files, as lowercase hex: what a results file
// records of each input so that the input can be recognised later.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <future>
#include <string>

namespace sphkern {

// The whole file, read in chunks; throws Error(input) if it cannot be read. `stop`, where
// given, is asked between chunks: true gives up (the digest is then empty).
std::string file_sha256_hex(const std::filesystem::path& file, const std::function<bool()>& stop = {});

// A file's digest computed on a thread of its own while the command goes on (an input of
// gigabytes takes seconds to hash, which the command's own work then hides). get() waits for
// it and throws what the hash threw; a digest no longer wanted stops at its next chunk.
class FileDigest {
public:
    explicit FileDigest(const std::filesystem::path& file);
    ~FileDigest();
    FileDigest(const FileDigest&) = delete;
    FileDigest& operator=(const FileDigest&) = delete;
    std::string get();

private:
    std::atomic<bool> stop_{false};
    std::future<std::string> digest_;
};

} // namespace sphkern
