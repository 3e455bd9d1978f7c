// PySPH: h = hdx dx from the particle spacing, support radius_scale h, a pair's h the mean.
#pragma once

#include "codes/code_profile.hpp"

namespace sphkern {

CodeProfile pysph_code();

} // namespace sphkern
