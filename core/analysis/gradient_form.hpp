// The pressure-gradient interpolations of the free-surface and block sums, and the weight
// each gives a pair for the hydrostatic pressure P = rho0 g depth (share/docs/method.md
// section 6). Written once for the surface profile and the block.
#pragma once

#include <string>

namespace sphkern {

// sum (P_i + P_j), difference (P_j - P_i), or Monaghan's
// rho_i sum m_j (P_i / rho_i^2 + P_j / rho_j^2) with per-particle densities.
enum class GradientForm { sum, difference, monaghan };

// Throws Error(input) on a name other than sum, difference or monaghan.
GradientForm parse_gradient_form(const std::string& text);
const char* gradient_form_name(GradientForm form);

// The weight of pair (i, j) with depths depth_i, depth_j (P in units of rho0 g) and
// relative densities rho_i, rho_j (read by the Monaghan form only). A template so that
// the block's loops over a run have no branch and vectorise.
template <GradientForm form>
inline double gradient_form_weight(double depth_i, double depth_j, double rho_i, double rho_j)
{
    if constexpr (form == GradientForm::sum) return depth_i + depth_j;
    else if constexpr (form == GradientForm::difference) return depth_j - depth_i;
    else return rho_i * (depth_i / (rho_i * rho_i) + depth_j / (rho_j * rho_j));
}

inline double gradient_form_weight(GradientForm form, double depth_i, double depth_j, double rho_i, double rho_j)
{
    switch (form) {
    case GradientForm::sum: return gradient_form_weight<GradientForm::sum>(depth_i, depth_j, rho_i, rho_j);
    case GradientForm::difference:
        return gradient_form_weight<GradientForm::difference>(depth_i, depth_j, rho_i, rho_j);
    case GradientForm::monaghan: break;
    }
    return gradient_form_weight<GradientForm::monaghan>(depth_i, depth_j, rho_i, rho_j);
}

} // namespace sphkern
