#include "support/io/sha256.hpp"

#include "support/error.hpp"

#include <fmt/format.h>
#include <openssl/evp.h>

#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace sphkern {

namespace {

using Context = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

} // namespace

std::string file_sha256_hex(const std::filesystem::path& file, const std::function<bool()>& stop)
{
    std::ifstream in(file, std::ios::binary);
    if (!in) fail_input(file.string() + ": cannot be read to compute its SHA-256");
    // OpenSSL's digest: the processor's SHA instructions where it has them (gigabytes a second).
    const Context context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
    if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("OpenSSL's SHA-256 cannot be set up");
    std::vector<char> buffer(1 << 20);
    while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0) {
        if (stop && stop()) return {};
        EVP_DigestUpdate(context.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) fail_input(file.string() + ": read error while computing its SHA-256");
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(context.get(), digest, &length);
    std::string hex;
    for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
    return hex;
}

FileDigest::FileDigest(const std::filesystem::path& file)
    : digest_(std::async(std::launch::async,
                         [this, file] { return file_sha256_hex(file, [this] { return stop_.load(); }); }))
{}

FileDigest::~FileDigest()
{
    stop_ = true;
    if (digest_.valid()) digest_.wait();
}

std::string FileDigest::get() { return digest_.get(); }

} // namespace sphkern
