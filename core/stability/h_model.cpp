#include "stability/h_model.hpp"

#include "support/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sphkern {

std::string h_model_name(HModel model) { return model == HModel::fixed ? "fixed" : "adaptive"; }

HModel parse_h_model(const std::string& text, const std::string& what)
{
    if (text == "fixed") return HModel::fixed;
    if (text == "adaptive") return HModel::adaptive;
    throw Error(ExitCode::usage,
                fmt::format("{} \"{}\" is not a smoothing-length model, expected fixed or adaptive", what, text),
                ErrorKind::unknown_name);
}

HDerivatives h_derivatives(double q, double w, double wq, double wqq, double h, int dim)
{
    const double D = dim, hd1 = std::pow(h, dim + 1), hd2 = hd1 * h;
    return {-(D * w + q * wq) / hd1, (D * (D + 1) * w + 2 * (D + 1) * q * wq + q * q * wqq) / hd2,
            -((D + 1) * wq + q * wqq) / hd2};
}

DispersionCoefficients dispersion_coefficients(HModel model, double gamma, double rho, double h, int dim, double Z,
                                               double Z2)
{
    if (model == HModel::fixed) return {(1 - 2 / gamma) / (rho * rho), 0, 2 / (gamma * rho), 1};
    // h = eta (m/rho)^(1/D): dh/drho = -h / (D rho), so delta rho = -(C^H xi) / Omega, and
    // Omega, P / (Omega rho^2) and h are perturbed with it (the method document, "Adaptive h").
    const double D = dim, Omega = 1 + h * Z / (D * rho);
    const double f0 = 1 / (gamma * Omega * rho);                                    // P / (Omega rho^2)
    const double c1 = ((1 + D) * h * Z + h * h * Z2) / (D * D * rho * rho * Omega); // d Omega per unit C^H xi
    const double alpha = ((gamma - 2) / rho + c1) / Omega, beta = h / (D * rho * Omega);
    return {f0 * alpha, f0 * beta, 2 * f0, Omega};
}

} // namespace sphkern
