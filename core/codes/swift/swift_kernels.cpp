#include "codes/swift/swift_kernels.hpp"

#include "codes/swift/swift.hpp"

namespace sphkern {

namespace {

const std::vector<CodeKernel>& kernels()
{
    static const std::vector<CodeKernel> all = swift_code().kernels;
    return all;
}

} // namespace

std::string sphkern_kernel_of_swift(const std::string& label)
{
    for (const auto& k : kernels())
        if (label == k.code_name) return k.kernel;
    return {};
}

std::string swift_kernel_label(const std::string& kernel)
{
    for (const auto& k : kernels())
        if (kernel == k.kernel) return k.code_name;
    return {};
}

} // namespace sphkern
