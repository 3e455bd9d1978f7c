#include "support/io/provenance.hpp"

#include "support/io/build_info.hpp"

#include <nlohmann/json.hpp>

#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace sphkern {

namespace {

std::vector<std::string>& command_line()
{
    static std::vector<std::string> words;
    return words;
}

// A string JSON can hold: bytes that are not UTF-8 (a file name) become U+FFFD.
std::string json_safe(const std::string& text)
{
    return nlohmann::json::parse(nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace))
        .get<std::string>();
}

std::string cpu_model()
{
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            auto colon = line.find(':');
            if (colon != std::string::npos) return json_safe(line.substr(line.find_first_not_of(" \t", colon + 1)));
        }
    return "unknown";
}

std::string utc_now()
{
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    char text[32];
    if (!::gmtime_r(&now, &utc) || !std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc)) return "unknown";
    return text;
}

} // namespace

void record_command_line(int argc, const char* const* argv)
{
    command_line().clear();
    for (int i = 0; i < argc; ++i) command_line().push_back(json_safe(argv[i]));
}

nlohmann::json provenance()
{
    static const std::string cpu = cpu_model();
    return {{"sphkern_version", SPHKERN_VERSION},
            {"git_describe", build_info::git_describe},
            {"build_type", build_info::build_type},
            {"compiler", build_info::compiler},
            {"date_utc", utc_now()},
            {"command_line", command_line()},
            {"host", {{"cpu", cpu}, {"threads", std::thread::hardware_concurrency()}}}};
}

std::string version_text()
{
    return std::string("sphkern ") + SPHKERN_VERSION + " (git " + build_info::git_describe + ", " +
           build_info::build_type + ", " + build_info::compiler + ")";
}

} // namespace sphkern
