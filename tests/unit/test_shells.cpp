// Shells against known coordination sequences and volume coefficients (share/docs/method.md section 3).
#include "lattices/shells.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>

#include <map>

#include <cmath>

using namespace sphkern;

namespace {

std::vector<int> counts(const std::string& lattice, int n, int site = 0)
{
    auto shells = lattice_shells(load_lattice(lattice), site, 8.0);
    std::vector<int> c;
    for (int i = 0; i < n && i < static_cast<int>(shells.size()); ++i) c.push_back(shells[i].count);
    return c;
}

} // namespace

TEST_CASE("coordination sequences of the shipped lattices")
{
    CHECK(counts("fcc", 8) == std::vector<int>{12, 6, 24, 12, 24, 8, 48, 6});
    CHECK(counts("bcc", 6) == std::vector<int>{8, 6, 12, 24, 8, 6});
    CHECK(counts("bcc", 6, 1) == std::vector<int>{8, 6, 12, 24, 8, 6});
    CHECK(counts("sc", 6) == std::vector<int>{6, 12, 8, 6, 24, 24});
    CHECK(counts("triangular", 8) == std::vector<int>{6, 6, 6, 12, 6, 6, 12, 6});
    CHECK(counts("hcp", 6) == std::vector<int>{12, 6, 2, 18, 12, 6});
    CHECK(counts("hcp", 6, 1) == std::vector<int>{12, 6, 2, 18, 12, 6});
    CHECK(counts("square", 6) == std::vector<int>{4, 4, 4, 8, 4, 4});
    // Hexagonal prism: 6 in-plane + 2 above/below at d, then 12 at sqrt(2) d.
    CHECK(counts("hex_prism", 2) == std::vector<int>{8, 12});
}

TEST_CASE("triangular shell radii are those of share/docs/method.md section 2")
{
    auto shells = lattice_shells(load_lattice("triangular"), 0, 4.0);
    std::vector<double> expected = {1, std::sqrt(3.0), 2, std::sqrt(7.0), 3, 2 * std::sqrt(3.0), std::sqrt(13.0), 4};
    REQUIRE(shells.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        CHECK(shells[i].radius == doctest::Approx(expected[i]).epsilon(1e-13));
}

TEST_CASE("directional moments: the trace of sum r^ r^T is the shell count")
{
    for (const char* name : {"fcc", "hcp", "bcc", "triangular"})
        for (const auto& s : lattice_shells(load_lattice(name), 0, 4.0))
            CHECK(s.moment.trace() == doctest::Approx(s.count).epsilon(1e-12));
    // Cubic symmetry: the moment along any axis is count / 3.
    for (const auto& s : lattice_shells(load_lattice("sc"), 0, 4.0))
        CHECK(s.directional_moment(Eigen::Vector3d(0, 0, 1)) == doctest::Approx(s.count / 3.0).epsilon(1e-12));
}

TEST_CASE("voronoi volume coefficients of share/docs/method.md section 3")
{
    CHECK(load_lattice("triangular").volume_coefficient("voronoi") ==
          doctest::Approx(std::sqrt(3.0) / 2).epsilon(1e-14));
    CHECK(load_lattice("square").volume_coefficient("voronoi") == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(load_lattice("sc").volume_coefficient("voronoi") == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(load_lattice("fcc").volume_coefficient("voronoi") == doctest::Approx(1 / std::sqrt(2.0)).epsilon(1e-14));
    CHECK(load_lattice("hcp").volume_coefficient("voronoi") == doctest::Approx(1 / std::sqrt(2.0)).epsilon(1e-14));
    CHECK(load_lattice("bcc").volume_coefficient("voronoi") ==
          doctest::Approx(4 / (3 * std::sqrt(3.0))).epsilon(1e-14));
    CHECK(load_lattice("hex_prism").volume_coefficient("voronoi") ==
          doctest::Approx(std::sqrt(3.0) / 2).epsilon(1e-14));
    CHECK(load_lattice("triangular").volume_coefficient("ball") == doctest::Approx(M_PI / 4));
    CHECK(load_lattice("fcc").volume_coefficient("ball") == doctest::Approx(M_PI / 6));
    CHECK(load_lattice("fcc").volume_coefficient("cube") == 1.0);
    CHECK(load_lattice("fcc").volume_coefficient("0.75") == 0.75);
    CHECK_THROWS_AS(load_lattice("fcc").volume_coefficient("-1"), Error);
    CHECK_THROWS_AS(load_lattice("fcc").volume_coefficient("voronio"), Error);
}

TEST_CASE("all seven lattices have the textbook first shell at d and shells up to 6 d at every site")
{
    // Coordination numbers: the textbook values; hex_prism is 6 in the layer and 2 above and below.
    const std::map<std::string, int> first = {{"triangular", 6}, {"square", 4}, {"fcc", 12},     {"bcc", 8},
                                              {"sc", 6},         {"hcp", 12},   {"hex_prism", 8}};
    CHECK(shipped_lattice_names().size() == 7);
    for (const auto& name : shipped_lattice_names()) {
        CAPTURE(name);
        auto lattice = load_lattice(name);
        for (int site = 0; site < lattice.sites(); ++site) {
            const auto shells = lattice_shells(lattice, site, 6.0);
            REQUIRE(!shells.empty());
            CHECK(shells.front().radius == doctest::Approx(1.0));
            CHECK(shells.front().count == first.at(name));
            CHECK(shells.back().radius <= 6.0 + 1e-12);
        }
    }
}

TEST_CASE("bad radii and sites are refused before any enumeration")
{
    auto fcc = load_lattice("fcc");
    CHECK_THROWS_WITH_AS(lattice_shells(fcc, 0, 0.0), doctest::Contains("positive"), Error);
    CHECK_THROWS_WITH_AS(lattice_shells(fcc, 0, -2.0), doctest::Contains("positive"), Error);
    CHECK_THROWS_WITH_AS(lattice_shells(fcc, 0, NAN), doctest::Contains("positive"), Error);
    CHECK_THROWS_WITH_AS(lattice_shells(fcc, 0, 1e6), doctest::Contains("limit"), Error);
    CHECK_THROWS_WITH_AS(lattice_shells(fcc, 3, 2.0), doctest::Contains("sites"), Error);
}
