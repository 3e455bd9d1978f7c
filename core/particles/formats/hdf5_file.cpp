#include "particles/formats/hdf5_file.hpp"

#include <mutex>

namespace sphkern::hdf5 {

void silence_hdf5()
{
    static std::once_flag once;
    std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

extern "C" herr_t follow_external_link(const char*, const char* group, const char* child_file, const char* child_object,
                                       unsigned*, hid_t, void* data)
{
    auto& linked = *static_cast<LinkedFiles*>(data);
    return linked.admit(child_file, "HDF5_EXT_PREFIX",
                        fmt::format("the external link in {} to {}:{}", group, child_file, child_object))
               ? 0
               : -1;
}

} // namespace sphkern::hdf5
