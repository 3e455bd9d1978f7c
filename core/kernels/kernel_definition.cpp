#include "kernels/kernel_definition.hpp"

namespace sphkern {

bool KernelDefinition::supports(int dim) const
{
    for (int d : dimensions)
        if (d == dim) return true;
    return false;
}

std::string KernelDefinition::dimensions_text() const
{
    std::string s;
    for (int d : dimensions) {
        if (!s.empty()) s += ',';
        s += std::to_string(d);
    }
    return s;
}

} // namespace sphkern
