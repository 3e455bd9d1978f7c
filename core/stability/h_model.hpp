// How the smoothing length behaves when the particles move (the method document, "Adaptive
// h"): fixed (h = k d for ever) or adaptive (h_i = eta (m / rho_i)^(1/D) with the grad-h
// terms of the momentum equation). In both the equilibrium h is k d; eta follows from it.
#pragma once

#include <string>

namespace sphkern {

enum class HModel { fixed, adaptive };

std::string h_model_name(HModel model);
// "fixed" or "adaptive"; Error(usage) naming `what` otherwise.
HModel parse_h_model(const std::string& text, const std::string& what);

// The h-derivatives of one neighbour's kernel terms, W(r, h) = w(q) / h^D with q = r / h,
// from the kernel's dimensionless w, dw/dq and d2w/dq2 at q:
struct HDerivatives {
    double dw_dh = 0;    // dW/dh = -(D w + q w') / h^(D+1)
    double d2w_dh2 = 0;  // d2W/dh2 = (D (D+1) w + 2 (D+1) q w' + q^2 w'') / h^(D+2)
    double dgrad_dh = 0; // d/dh of dW/dr = -((D+1) w' + q w'') / h^(D+2)
};
HDerivatives h_derivatives(double q, double w, double wq, double wqq, double h, int dim);

// The coefficients of the dispersion matrix
//   M = gradient C C^H - cross (C Ch^H + Ch C^H) + hessian K
// (C of the kernel gradients, Ch of their h-derivatives, K of the Hessians, each times m and
// the phases), at the SPH density rho, with c = 1, P / rho = 1 / gamma and, for adaptive h,
// Z = sum_j m dW_ij/dh and Z2 = sum_j m d2W_ij/dh2 (the particle's own term included).
struct DispersionCoefficients {
    double gradient = 0, cross = 0, hessian = 0;
    double omega = 1; // the grad-h factor 1 + h Z / (D rho) (1 for fixed h)
};
DispersionCoefficients dispersion_coefficients(HModel model, double gamma, double rho, double h, int dim, double Z,
                                               double Z2);

} // namespace sphkern
