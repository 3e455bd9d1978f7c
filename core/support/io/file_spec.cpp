#include "support/io/file_spec.hpp"

namespace sphkern {

namespace fs = std::filesystem;

bool looks_like_path(const std::string& spec, const std::vector<std::string>& extensions)
{
    if (spec.find('/') != std::string::npos) return true;
    for (const auto& e : extensions)
        if (spec.size() > e.size() && spec.ends_with(e)) return true;
    return false;
}

std::string resolve_beside(const std::string& spec, const fs::path& file, const std::vector<std::string>& extensions)
{
    if (spec.empty()) return spec;
    const fs::path path(spec);
    std::error_code ec;
    if (path.is_absolute()) return spec;
    const fs::path beside = (file.parent_path() / path).lexically_normal();
    if (fs::is_regular_file(beside, ec)) return beside.string();
    if (spec.find('+') != std::string::npos) {
        std::string joined;
        std::size_t from = 0;
        for (std::size_t plus;; from = plus + 1) {
            plus = spec.find('+', from);
            const std::string part = spec.substr(from, plus == std::string::npos ? std::string::npos : plus - from);
            joined += (from ? "+" : "") +
                      (part.find('+') == std::string::npos ? resolve_beside(part, file, extensions) : part);
            if (plus == std::string::npos) break;
        }
        return joined;
    }
    return looks_like_path(spec, extensions) ? beside.string() : spec;
}

} // namespace sphkern
