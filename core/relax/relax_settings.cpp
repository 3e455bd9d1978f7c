#include "relax/relax_settings.hpp"

namespace sphkern {

const char* relax_method_name(RelaxMethod method) { return method == RelaxMethod::pressure ? "pressure" : "shift"; }

} // namespace sphkern
