#include "codes/code_table.hpp"

#include "codes/dualsphysics/dualsphysics.hpp"
#include "codes/gadget2/gadget2.hpp"
#include "codes/gadget4/gadget4.hpp"
#include "codes/phantom/phantom.hpp"
#include "codes/pysph/pysph.hpp"
#include "codes/splishsplash/splishsplash.hpp"
#include "codes/swift/swift.hpp"
#include "support/error.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>
#include <stdexcept>

namespace sphkern {

const std::vector<CodeProfile>& code_profiles()
{
    static const std::vector<CodeProfile> all{swift_code(), phantom_code(),      gadget2_code(),     gadget4_code(),
                                              pysph_code(), dualsphysics_code(), splishsplash_code()};
    return all;
}

const std::vector<const CodeProfile*>& study_codes()
{
    static const std::vector<const CodeProfile*> codes = [] {
        std::vector<const CodeProfile*> out;
        for (const auto& p : code_profiles())
            if (!p.sets_volume) out.push_back(&p);
        return out;
    }();
    return codes;
}

const CodeProfile& code_profile(const std::string& name, const ValueSource& source)
{
    std::vector<std::string> names;
    for (const auto& p : code_profiles()) {
        if (p.name == name) return p;
        names.push_back(p.name);
    }
    source.fail(fmt::format("\"{}\" is unknown, expected one of {}{}", name, fmt::join(names, ", "),
                            did_you_mean(name, names)),
                ErrorKind::unknown_name);
}

namespace {

bool in(const std::vector<int>& dimensions, int dimension)
{
    return std::find(dimensions.begin(), dimensions.end(), dimension) != dimensions.end();
}

// sphkern's names of the kernels the code ships in `dimension`.
std::vector<std::string> kernels_in(const CodeProfile& p, int dimension)
{
    std::vector<std::string> names;
    for (const auto& k : p.kernels)
        if (in(k.dimensions, dimension)) names.push_back(k.kernel);
    return names;
}

std::string dimensions_text(const std::vector<int>& dimensions)
{
    std::vector<std::string> words;
    for (int d : dimensions) words.push_back(fmt::format("{}D", d));
    if (words.size() == 1) return words[0];
    return fmt::format("{} and {}", fmt::join(words.begin(), words.end() - 1, ", "), words.back());
}

} // namespace

bool code_ships(const CodeProfile& p, const Kernel& kernel, int dimension)
{
    const auto names = kernels_in(p, dimension);
    return in(p.dimensions, dimension) && std::find(names.begin(), names.end(), kernel.name()) != names.end();
}

void require_code_kernel(const CodeProfile& p, const Kernel& kernel, int dimension)
{
    if (!in(p.dimensions, dimension))
        fail_usage(fmt::format("{}: {} runs in {} only, not in {}D", kernel.name(), p.name,
                               dimensions_text(p.dimensions), dimension));
    if (code_ships(p, kernel, dimension)) return;
    const auto names = kernels_in(p, dimension);
    std::vector<int> elsewhere;
    for (const auto& k : p.kernels)
        if (k.kernel == kernel.name()) elsewhere = k.dimensions;
    const std::string has = elsewhere.empty()
                                ? fmt::format("does not ship it; its kernels are {}", fmt::join(names, ", "))
                                : fmt::format("has it in {} only; its kernels in {}D are {}",
                                              dimensions_text(elsewhere), dimension, fmt::join(names, ", "));
    if (!p.user_kernels) fail_usage(fmt::format("{}: {} {}", kernel.name(), p.name, has));
    // Said once a run: a command may check its kernel more than once.
    static std::mutex said_mutex;
    static std::set<std::string> said;
    const std::string line =
        fmt::format("{}: {} {}; taken as a user's kernel, which {} accepts", kernel.name(), p.name, has, p.title);
    const std::lock_guard lock(said_mutex);
    if (said.insert(line).second) spdlog::warn("{}", line);
}

double code_volume(const CodeProfile& p, int dim, double value)
{
    if (!p.sets_volume) throw std::logic_error(p.name + " does not fix the volume");
    return splishsplash_volume(dim, value);
}

void require_lattice_volume(const CodeProfile& p, const std::string& what)
{
    if (p.sets_volume)
        fail_input(fmt::format("{}: its particle radius fixes the particle volume too (0.8 (2 r)^D), which {} cannot "
                               "take: expected eps or surface, which take the code's volume",
                               p.name, what));
}

StabilityPressure stability_pressure(const CodeProfile* code, double gamma, std::optional<double> coef_sound,
                                     const ValueSource& source)
{
    const bool tait = code && code->rest_pressure == RestPressure::tait;
    if (coef_sound && !tait) {
        std::vector<std::string> codes;
        for (const auto& p : code_profiles())
            if (p.rest_pressure == RestPressure::tait) codes.push_back(p.name);
        source.fail(
            fmt::format("{:g}: the sound speed over sqrt(g H) of a weakly compressible code ({}); expected --code "
                        "naming one",
                        *coef_sound, fmt::join(codes, ", ")));
    }
    if (!tait)
        return {gamma, false, 0, fmt::format("an ideal gas at rest, P0 / rho = c^2 / gamma (gamma = {:g})", gamma)};
    const double c = coef_sound.value_or(code->coef_sound);
    // P0 / (rho c^2) from 1e-6 (gamma's largest) to 1: a sound speed of 1 to 1000 sqrt(g H).
    if (!(c >= 1 && c <= 1000)) source.fail(fmt::format("{:g}: expected a number in [1, 1000]", c));
    return {
        c * c, true, c,
        fmt::format("Tait's pressure at rest ({}): hydrostatic, up to rho c^2 / {:.4g} (c = {:.4g} sqrt(g H)), the top "
                    "of its range deciding",
                    code->title, c * c, c)};
}

double code_support_per_h(const CodeProfile& p, const Kernel& kernel, int dim) { return p.support_per_h(kernel, dim); }

double code_parameter(const CodeProfile& p, const Kernel& kernel, int dim, double a_p, double k, double eps_rho)
{
    const double rest_spacing = std::pow(a_p, 1.0 / dim);
    // (m / rho)^(1/D) in units of d: the code's own density where it solves for h.
    const double spacing = p.from_sph_density ? std::pow(a_p / (1 + eps_rho), 1.0 / dim) : rest_spacing;
    return p.parameter_of(kernel, dim, k, spacing);
}

double k_of_code_parameter(const CodeProfile& p, const Kernel& kernel, int dim, double a_p, double value, double k_max,
                           const std::function<double(double)>& eps_rho, const ValueSource& source)
{
    // At rest spacing the parameter is a power of k: its k is the start of the search.
    const double power = p.counts_neighbours ? dim : 1;
    const double at_one = code_parameter(p, kernel, dim, a_p, 1, 0);
    const double guess = std::pow(value / at_one, 1 / power);
    if (!p.from_sph_density) return guess;
    // With the SPH density it grows with k (each neighbour's W(r / H) does) and is flat where no
    // neighbour is inside the support: bracket the value, then solve.
    auto f = [&](double k) { return code_parameter(p, kernel, dim, a_p, k, eps_rho(k)) - value; };
    double lo = std::min(guess, k_max), hi = lo;
    while (f(lo) > 0 && lo > 1e-3) lo /= 1.25;
    while (f(hi) < 0 && hi < k_max) hi = std::min(k_max, hi * 1.25);
    if (f(lo) > 0)
        source.fail(
            fmt::format("{:g}: expected more than {:.6g}, the {} of a particle with no neighbour inside its support",
                        value, f(lo) + value, p.parameter));
    if (f(hi) < 0)
        source.fail(
            fmt::format("{:g}: expected at most {:.6g}, the {} at k = {:g}", value, f(hi) + value, p.parameter, hi));
    std::uintmax_t iterations = 200;
    const auto [a, b] = boost::math::tools::toms748_solve(
        f, lo, hi, [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(1.0, std::abs(x)); },
        iterations);
    return 0.5 * (a + b);
}

} // namespace sphkern
