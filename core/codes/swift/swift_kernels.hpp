// The kernels SWIFT ships, as its snapshots name them in /HydroScheme "Kernel function"
// (its kernel_hydro.h), and sphkern's names for them.
#pragma once

#include <string>

namespace sphkern {

// "wendland_c2" for "Wendland C2"; "" for a kernel sphkern does not ship.
std::string sphkern_kernel_of_swift(const std::string& label);
// "Wendland C2" for "wendland_c2"; "" for a kernel SWIFT does not ship.
std::string swift_kernel_label(const std::string& kernel);

} // namespace sphkern
