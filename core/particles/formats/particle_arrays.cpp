#include "particles/formats/particle_arrays.hpp"

#include <algorithm>

namespace sphkern {

std::vector<std::string> particle_array_names(const std::string& list)
{
    std::vector<std::string> names;
    if (list.empty()) return names;
    for (std::size_t start = 0;;) {
        const std::size_t end = list.find(',', start);
        names.push_back(list.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) return names;
        start = end + 1;
    }
}

std::string particle_array_list_problem(const std::string& list)
{
    const auto names = particle_array_names(list);
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i].empty()) return "an empty array name; expected names separated by commas";
        if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
            names.begin() + static_cast<std::ptrdiff_t>(i))
            return "array \"" + names[i] + "\" named twice; expected each array once";
    }
    return {};
}

} // namespace sphkern
