// Which VTK file an output option such as --vtk writes, told by its name: .vtk the legacy
// ASCII format, .vtu ParaView's XML UnstructuredGrid (support/io/vtk_xml.hpp).
#pragma once

#include <string>

namespace sphkern {

enum class VtkFormat { legacy, xml };

// The extension in any case; any other is refused with Error(usage), naming `option`, the
// path and the extensions it takes.
VtkFormat vtk_format_of(const std::string& path, const std::string& option);

} // namespace sphkern
