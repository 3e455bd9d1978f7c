#include "kernels/kernel_spectrum.hpp"

#include "support/process/interruption.hpp"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>

namespace sphkern {

std::vector<std::pair<double, double>> spectrum_curve(const Kernel& kernel, int dim, double k, double kh_max, int n)
{
    std::vector<std::pair<double, double>> curve;
    for (int i = 0; i <= n; ++i) {
        if ((i & 63) == 0) throw_if_interrupted(); // each point is a quadrature: a signal stops the curve
        const double kh = kh_max * i / n;
        curve.emplace_back(kh, kernel.fourier(kh, dim, k));
    }
    return curve;
}

SpectrumSummary spectrum_summary(const Kernel& kernel, int dim, double k)
{
    const int n = 1000;
    const double step = spectrum_kh_max / n;
    auto curve = spectrum_curve(kernel, dim, k, spectrum_kh_max, n);
    auto f = [&](double kh) { return kernel.fourier(kh, dim, k); };
    SpectrumSummary s;
    s.dimension = dim;
    s.provided = kernel.provides_fourier_transform();
    std::size_t lowest = 0;
    for (std::size_t i = 1; i < curve.size(); ++i)
        if (curve[i].second < curve[lowest].second) lowest = i;
    s.at = curve[lowest].first;
    s.minimum = curve[lowest].second;
    if (lowest > 0 && lowest + 1 < curve.size()) {
        std::uintmax_t iterations = 100;
        auto [x, fx] = boost::math::tools::brent_find_minima(f, s.at - step, s.at + step, 40, iterations);
        if (fx < s.minimum) s.at = x, s.minimum = fx;
    }
    for (std::size_t i = 1; i < curve.size(); ++i) {
        const double a = curve[i - 1].second, b = curve[i].second;
        if (b == 0) {
            s.first_zero = curve[i].first;
            break;
        }
        if ((a > 0) != (b > 0)) {
            std::uintmax_t iterations = 100;
            auto r = boost::math::tools::toms748_solve(f, curve[i - 1].first, curve[i].first, a, b,
                                                       boost::math::tools::eps_tolerance<double>(45), iterations);
            s.first_zero = 0.5 * (r.first + r.second);
            break;
        }
    }
    return s;
}

} // namespace sphkern
