// libFuzzer harness for the shell generator: the bytes choose a basis, a motif, a site
// and a radius; the shells must satisfy their invariants or the request be refused.
#include "lattices/lattice.hpp"
#include "lattices/shells.hpp"
#include "support/error.hpp"

#include <fuzzer/FuzzedDataProvider.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    FuzzedDataProvider in(data, size);
    const int dim = in.ConsumeBool() ? 3 : 2;
    nlohmann::json document = {{"name", "fuzz"}, {"dimension", dim}};
    for (int i = 0; i < dim; ++i) {
        nlohmann::json vector = nlohmann::json::array();
        for (int c = 0; c < dim; ++c) vector.push_back(in.ConsumeFloatingPointInRange<double>(-4, 4));
        document["basis"].push_back(vector);
    }
    const int sites = in.ConsumeIntegralInRange(1, 4);
    for (int s = 0; s < sites; ++s) {
        nlohmann::json site = nlohmann::json::array();
        for (int c = 0; c < dim; ++c) site.push_back(in.ConsumeFloatingPointInRange<double>(0, 1));
        document["motif"].push_back(site);
    }
    const int site = in.ConsumeIntegralInRange(0, sites - 1);
    const double radius = in.ConsumeFloatingPointInRange<double>(-1, 6);
    try {
        auto lattice = sphkern::parse_lattice(document, "fuzz.json");
        auto shells = sphkern::lattice_shells(lattice, site, radius);
        double previous = 0;
        for (const auto& s : shells) {
            // Invariants: increasing radii at least d apart from the particle, no empty
            // shell, and the trace of sum r^ r^T equal to the count.
            if (s.count <= 0 || s.radius <= previous || s.radius < 1 - 1e-9 || s.radius > radius * (1 + 1e-9))
                std::abort();
            if (std::abs(s.moment.trace() - s.count) > 1e-9 * s.count) std::abort();
            previous = s.radius;
        }
    } catch (const sphkern::Error&) {}
    return 0;
}
