// ParaView's XML formats as bytes: the appended blocks where the header's offsets say, each
// double as it is; the collection's entries; the series' names; --vtk's extensions.
#include "support/error.hpp"
#include "support/io/vtk_format.hpp"
#include "support/io/vtk_xml.hpp"

#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <regex>
#include <sstream>
#include <vector>

using namespace sphkern;

namespace {

// The block at `offset` after the '_' of the appended data: its byte count, then its bytes.
std::string appended_block(const std::string& file, std::size_t offset)
{
    const std::size_t start = file.find("encoding=\"raw\">\n   _") + std::strlen("encoding=\"raw\">\n   _") + offset;
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, file.data() + start, sizeof bytes);
    return file.substr(start + sizeof bytes, bytes);
}

std::vector<double> doubles(const std::string& bytes)
{
    std::vector<double> values(bytes.size() / sizeof(double));
    std::memcpy(values.data(), bytes.data(), bytes.size());
    return values;
}

std::size_t offset_of(const std::string& file, const std::string& name)
{
    std::smatch match;
    REQUIRE(std::regex_search(file, match, std::regex("Name=\"" + name + "\"[^>]*offset=\"([0-9]+)\"")));
    return std::stoul(match[1]);
}

} // namespace

TEST_CASE("vtk xml: a .vtu's appended blocks hold the points, the arrays and one vertex cell a point")
{
    const std::vector<double> x{0.1, 1.0 / 3}, y{2, -0.0}, h{1e-300, 7};
    std::ostringstream out;
    write_vtu(out, {x, y, {}},
              {{"h", 1, [&](std::size_t i, int) { return h[i]; }},
               {"e1", 3, [](std::size_t i, int c) { return 10.0 * static_cast<double>(i) + c; }}});
    const std::string file = out.str();
    const std::string order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
    CHECK(file.find("byte_order=\"" + order + "\" header_type=\"UInt64\"") != std::string::npos);
    CHECK(file.find("NumberOfPoints=\"2\" NumberOfCells=\"2\"") != std::string::npos);
    CHECK(doubles(appended_block(file, offset_of(file, "h"))) == h);
    CHECK(doubles(appended_block(file, offset_of(file, "e1"))) == std::vector<double>{0, 1, 2, 10, 11, 12});
    std::smatch points;
    REQUIRE(std::regex_search(file, points, std::regex("<Points>\\s*<DataArray[^>]*offset=\"([0-9]+)\"")));
    CHECK(doubles(appended_block(file, std::stoul(points[1]))) == std::vector<double>{0.1, 2, 0, 1.0 / 3, -0.0, 0});
    std::vector<std::int64_t> offsets(2);
    std::memcpy(offsets.data(), appended_block(file, offset_of(file, "offsets")).data(), 16);
    CHECK(offsets == std::vector<std::int64_t>{1, 2});
    CHECK(appended_block(file, offset_of(file, "types")) == std::string("\x01\x01"));
    CHECK(file.ends_with("\n  </AppendedData>\n</VTKFile>\n"));
}

TEST_CASE("vtk xml: a .pvd lists its files in order with their times, and a series' names sort")
{
    std::ostringstream out;
    write_pvd(out, {{0, "a_0.vtu"}, {0.25, "a&b_1.vtu"}});
    CHECK(out.str().find("<VTKFile type=\"Collection\"") != std::string::npos);
    CHECK(out.str().find("<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"a_0.vtu\"/>\n"
                         "    <DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"a&amp;b_1.vtu\"/>") !=
          std::string::npos);
    CHECK(pvd_member_path("out/run.pvd", 7, 200) == std::filesystem::path("out/run_007.vtu"));
    CHECK(pvd_member_path("run.pvd", 0, 9) == std::filesystem::path("run_0.vtu"));
}

TEST_CASE("vtk xml: --vtk takes .vtk and .vtu, in any case, and names the option for anything else")
{
    CHECK(vtk_format_of("a.vtk", "--vtk") == VtkFormat::legacy);
    CHECK(vtk_format_of("dir.x/a.VTU", "--vtk") == VtkFormat::xml);
    try {
        vtk_format_of("a.txt", "--vtk");
        FAIL("a.txt was taken");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::usage);
        CHECK(std::string(e.what()) ==
              "--vtk a.txt: expected a file name ending in .vtk (legacy VTK) or .vtu (ParaView's XML format)");
    }
}
