// Names against files: where a command line or a study takes "a name or a file".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// A spec names a file when it has a '/' or ends in one of `extensions`.
bool looks_like_path(const std::string& spec, const std::vector<std::string>& extensions);
inline bool looks_like_path(const std::string& spec, const std::string& extension)
{
    return looks_like_path(spec, std::vector<std::string>{extension});
}

// A spec read from `file` (a study): a relative path is relative to that file's folder. A
// name that exists there as a file is that file, whatever it contains ("a+b.so" is no
// blend then); a blend "A+B" has each part resolved; other names are left as they are.
std::string resolve_beside(const std::string& spec, const std::filesystem::path& file,
                           const std::vector<std::string>& extensions);

} // namespace sphkern
