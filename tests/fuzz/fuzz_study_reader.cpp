// libFuzzer harness: any bytes as a study file (parsing and validation, no run).
#include "study/study.hpp"
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
        sphkern::parse_study(std::move(document), "/nonexistent/fuzz.json");
    } catch (const sphkern::Error&) {}
    return 0;
}
