// libFuzzer harness: any bytes as a lattice file. A sphkern::Error is the expected
// answer to bad input; anything else (a crash, another exception, a sanitizer report) is a finding.
#include "lattices/lattice.hpp"
#include "lattices/shells.hpp"
#include "support/error.hpp"
#include "support/io/json_input.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    try {
        auto document = sphkern::parse_json_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
        auto lattice = sphkern::parse_lattice(document, "fuzz.json");
        for (int site = 0; site < lattice.sites() && site < 4; ++site) sphkern::lattice_shells(lattice, site, 2.5);
        for (const auto& c : lattice.volume_coefficients) lattice.volume_coefficient(c.name);
    } catch (const sphkern::Error&) {}
    return 0;
}
