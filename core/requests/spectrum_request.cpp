#include "requests/spectrum_request.hpp"

#include "requests/settings/command_settings.hpp"

#include "support/error.hpp"
#include "support/io/results_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace sphkern {

void check_spectrum_request(const SpectrumRequest& r, const SpectrumSources& sources)
{
    const SettingTable& declared = settings_of("spectrum");
    check_setting(declared["dim"], r.dimension, sources.dimension);
    check_setting(declared["k"], r.k, sources.k);
    check_setting(declared["max"], r.kh_max, sources.kh_max);
    check_setting(declared["points"], r.points, sources.points);
}

SpectrumResult run_spectrum(const SpectrumRequest& r, const SpectrumSources& sources, const Kernel& kernel)
{
    kernel.require_dimension(r.dimension, fmt::format("({})", sources.dimension.about(r.dimension)));
    SpectrumResult result{spectrum_curve(kernel, r.dimension, r.k, r.kh_max, r.points),
                          spectrum_summary(kernel, r.dimension, r.k)};
    for (const auto& [kh, value] : result.curve)
        if (!std::isfinite(value))
            fail_input(
                fmt::format("kernel {}: its Fourier transform is not finite at kappa h = {}", kernel.label(), kh));
    return result;
}

nlohmann::json spectrum_document(const SpectrumRequest& r, const SpectrumResult& result, const Kernel& kernel)
{
    const auto& summary = result.summary;
    nlohmann::json points = nlohmann::json::array();
    for (const auto& [kh, value] : result.curve) points.push_back({kh, value});
    return {{"kernel", kernel.label()},
            {"dimension", r.dimension},
            {"k", r.k},
            {"source", summary.provided ? "plugin" : "quadrature"},
            {"min", summary.minimum},
            {"at", summary.at},
            {"first_zero", summary.first_zero ? nlohmann::json(*summary.first_zero) : nlohmann::json()},
            {"curve", points}};
}

void print_spectrum(const SpectrumRequest& r, const SpectrumResult& result, const Kernel& kernel)
{
    const auto& summary = result.summary;
    fmt::print(results_file(), "# Fourier transform of {} in {}D ({}): min {:.6g} at kappa h = {:.6g}, {}\n",
               kernel.label(), r.dimension, summary.provided ? "the plugin's" : "quadrature", summary.minimum,
               summary.at,
               summary.first_zero ? fmt::format("first zero at kappa h = {:.8g}", *summary.first_zero)
                                  : std::string("no zero on [0, 50]"));
    fmt::print(results_file(), "# kappa_h W_hat\n");
    for (const auto& [kh, value] : result.curve) fmt::print(results_file(), "{:.6f} {:.12g}\n", kh, value);
}

} // namespace sphkern
