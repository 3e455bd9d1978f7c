// An SPH code as sphkern models it: the setting of its resolution as the code defines it, the
// dimensions it runs and the kernels it has in each, and how its files store h. Each code fills
// one in its own folder (codes/<name>/<name>.cpp); codes/code_table lists them.
#pragma once

#include "kernels/kernel.hpp"

#include <string>
#include <vector>

namespace sphkern {

struct ValueSource;

// The layout of the initial conditions a code starts from (relax --code NAME --output): HDF5
// for SWIFT, GADGET and PySPH, Phantom's own full dump; none for a code that starts from files
// of its own that sphkern does not write (a .csv output holds its h).
enum class CodeLayout { swift, gadget, pysph, phantom, none };

// What a code's density solve counts: each neighbour's mass (h_i = c (m_i / rho_i)^(1/D) with
// rho_i = sum_j m_j W_ij) or each neighbour once (h_i = c (1 / n_i)^(1/D) with n_i = sum_j W_ij,
// the number density: masses do not enter).
enum class NeighbourCount { mass, number };

// The pressure of the code's particles at rest, which sets the pressure term of the dispersion
// relation (method.md, section 10): an ideal gas, P0 / rho = c^2 / gamma; or a weakly compressible
// fluid (Tait), whose pressure at rest is the hydrostatic one, from 0 to rho g H = rho c^2 /
// CoefSound^2 with c = CoefSound sqrt(g H).
enum class RestPressure { ideal_gas, tait };

// A kernel as the code names it, the sphkern kernel that is the same function, and the
// dimensions in which the code has it.
struct CodeKernel {
    std::string code_name; // "WendlandQuinticC2"
    std::string kernel;    // "wendland_c2"
    std::vector<int> dimensions;
};

struct CodeProfile {
    std::string name;                             // "swift"
    std::string title;                            // "SWIFT", as the code spells itself
    std::string parameter;                        // "eta": how the command line and Python name it
    std::string parameter_help;                   // the option's help: "SWIFT's eta, h = eta (m / rho)^(1/D)"
    std::string source;                           // where the code states its definition
    bool from_sph_density = false;                // h solved from the SPH density (else from the rest spacing)
    NeighbourCount counts = NeighbourCount::mass; // what that solve counts, and where the code says so
    std::string count_source;
    std::string count_switch; // the code's setting that makes it count the other way, empty if none
    // A bias the code subtracts from each particle's density, as a fraction of its own term
    // m_i W(0, h_i), for a kernel, dimension and parameter value; nullptr where it has none.
    // The switch that turns it on and where the code says so; the fraction's Error names `source`.
    std::string bias_switch, bias_source;
    double (*self_bias)(const Kernel& kernel, int dimension, double value, const ValueSource& source) = nullptr;
    RestPressure rest_pressure = RestPressure::ideal_gas;
    double coef_sound = 0; // Tait: the default c / sqrt(g H), and where the code sets it
    std::string coef_sound_source;
    std::vector<int> dimensions; // the dimensions the code runs
    std::vector<CodeKernel> kernels;
    bool user_kernels = false;      // the code takes a kernel it does not ship (a user's own)
    bool pair_mean = false;         // a pair's h in its sums is (h_i + h_j) / 2 (else h_i)
    bool sets_volume = false;       // the setting fixes the particle volume too (SPlisHSPlasH)
    bool counts_neighbours = false; // the parameter is a neighbour number, going as H^D (GADGET)
    CodeLayout layout = CodeLayout::none;
    // The ending the code's reader needs of an HDF5 file's name, and why ("" for any).
    std::string hdf5_suffix, hdf5_suffix_reason;
    // The support radius H over the h the code stores in its files.
    double (*support_per_h)(const Kernel& kernel, int dimension) = nullptr;
    // The code's parameter at h = k d for the spacing (m / rho)^(1/D) in d (the support radius H = R k d).
    double (*parameter_of)(const Kernel& kernel, int dimension, double k, double spacing) = nullptr;
};

} // namespace sphkern
