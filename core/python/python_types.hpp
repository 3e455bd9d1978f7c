// Arguments that the module checks itself (so that a wrong type is a ValueError naming the
// argument, not pybind11's TypeError) are taken as any Python object; Typed<"..."> is such an
// object shown with the type it stands for in the signatures help() prints.
#pragma once

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>

namespace sphkern {

template <std::size_t N>
struct TypeName {
    char text[N];
    constexpr TypeName(const char (&name)[N]) { std::copy_n(name, N, text); } // NOLINT: a literal's type
};

template <TypeName Name>
class Typed : public pybind11::object {
public:
    using pybind11::object::object;
    static bool check_(pybind11::handle h) { return h.ptr() != nullptr; } // any object: checked where it is used
};

using ArrayLike = Typed<"numpy.typing.ArrayLike">;
using PositionsOrFiles = Typed<"Union[numpy.typing.ArrayLike, str, os.PathLike, Sequence[str]]">;
using DictOrList = Typed<"Union[dict, list]">;
using OptionalArrayLike = Typed<"Optional[numpy.typing.ArrayLike]">;
using OptionalFloat = Typed<"Optional[float]">;
using OptionalSequence = Typed<"Optional[Sequence[float]]">;
using OptionalParams = Typed<"Optional[Dict[str, float]]">;
using NameOrNumber = Typed<"Union[str, float]">;
using NameOrPath = Typed<"Union[str, os.PathLike]">;
using VolumeArgument = Typed<"Union[str, numpy.typing.ArrayLike, None]">;
using OptionalNames = Typed<"Union[str, Sequence[str], None]">;
using IntSequence = Typed<"Sequence[int]">;
using OptionalIntSequence = Typed<"Optional[Sequence[int]]">;

} // namespace sphkern

namespace pybind11::detail {
template <sphkern::TypeName Name>
struct handle_type_name<sphkern::Typed<Name>> {
    static constexpr auto name = const_name(Name.text);
};
} // namespace pybind11::detail
