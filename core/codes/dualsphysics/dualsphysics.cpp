#include "codes/dualsphysics/dualsphysics.hpp"

#include <cmath>

namespace sphkern {

CodeProfile dualsphysics_code()
{
    // 2D and 3D cases; its kernels are the cubic spline and the Wendland C2 (quintic).
    const std::vector<int> dims{2, 3};
    CodeProfile p;
    p.name = "dualsphysics";
    p.title = "DualSPHysics";
    p.parameter = "coefh";
    p.parameter_help = "DualSPHysics' coefh, h = coefh sqrt(D) dp";
    p.source = "DualSPHysics' user guide: h = coefh sqrt(3 dp^2) (sqrt(2 dp^2) in 2D), support 2h";
    p.dimensions = dims;
    p.rest_pressure = RestPressure::tait;
    p.coef_sound = 20;
    p.coef_sound_source = "its case's CoefSound (default 20): c0 = CoefSound sqrt(g H)";
    p.kernels = {{"Cubic", "cubic_bspline", dims}, {"Wendland", "wendland_c2", dims}};
    p.support_per_h = [](const Kernel&, int) { return 2.0; };
    p.parameter_of = [](const Kernel& kernel, int dim, double k, double spacing) {
        return kernel.support() * k / (2 * std::sqrt(double(dim)) * spacing);
    };
    return p;
}

} // namespace sphkern
