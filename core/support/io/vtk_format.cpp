#include "support/io/vtk_format.hpp"

#include "support/error.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace sphkern {

VtkFormat vtk_format_of(const std::string& path, const std::string& option)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".vtk") return VtkFormat::legacy;
    if (extension == ".vtu") return VtkFormat::xml;
    throw Error(ExitCode::usage,
                option + " " + path +
                    ": expected a file name ending in .vtk (legacy VTK) or .vtu (ParaView's XML format)");
}

} // namespace sphkern
