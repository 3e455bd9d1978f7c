#include "particles/formats/swift_kernels.hpp"

#include <utility>

namespace sphkern {

namespace {

constexpr std::pair<const char*, const char*> kernels[] = {
    {"Cubic spline (M4)", "cubic_bspline"}, {"Quartic spline (M5)", "quartic_bspline"},
    {"Quintic spline (M6)", "morris_quintic"}, {"Wendland C2", "wendland_c2"},
    {"Wendland C4", "wendland_c4"},       {"Wendland C6", "wendland_c6"}};

} // namespace

std::string sphkern_kernel_of_swift(const std::string& label)
{
    for (const auto& [swift, sphkern] : kernels)
        if (label == swift) return sphkern;
    return {};
}

std::string swift_kernel_label(const std::string& kernel)
{
    for (const auto& [swift, sphkern] : kernels)
        if (kernel == sphkern) return swift;
    return {};
}

} // namespace sphkern
