// Relaxation: the SPH sums against a brute-force O(N^2) sum over periodic images, the
// pressure force on a lattice plane wave against the dispersion matrix of section 10, the
// energy of the undamped motion, determinism across thread counts, the written files read
// back, g(r) and the Poisson reference against independent values.
#include "helpers.hpp"
#include "particles/formats/particle_files.hpp"
#include "particles/formats/particle_writers.hpp"
#include "particles/poisson_reference.hpp"
#include "particles/smoothing_lengths.hpp"
#include "particles/sources/lattice_particles.hpp"
#include "particles/sources/poisson_particles.hpp"
#include "relax/glass_quality.hpp"
#include "relax/pairing_motion.hpp"
#include "relax/relaxation.hpp"
#include "requests/relax_request.hpp"
#include "stability/dispersion.hpp"
#include "support/error.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

using namespace sphkern;
using sphkern::test::shipped_kernel;

namespace {

ParticleSet poisson_set(std::size_t n, int dim, double side, std::uint64_t seed)
{
    PoissonSpec spec;
    spec.count = n, spec.dimension = dim, spec.seed = seed;
    spec.box = Eigen::Vector3d(side, side, side);
    return poisson_particles(spec);
}

ParticleSet lattice_block(const std::string& name, long long cells, double sigma = 0)
{
    LatticeBlockSpec spec;
    const Lattice lattice = load_lattice(name);
    spec.cells = {cells, cells, lattice.dimension == 3 ? cells : 1};
    spec.sigma = sigma;
    return lattice_particles(lattice, spec);
}

// rho_i, sum_j V grad_i W_ij and a_i written out from the definitions over all periodic images.
struct BruteSums {
    double density;
    Eigen::Vector3d gradient, acceleration;
};

std::vector<BruteSums> brute_sums(const Kernel& kernel, const ParticleSet& set, const ForceModel& m)
{
    const int dim = set.dimension;
    const double hd = std::pow(m.h, dim);
    std::vector<BruteSums> out(set.size(), {0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
    auto for_pairs = [&](auto&& visit) {
        for (std::size_t i = 0; i < set.size(); ++i)
            for (std::size_t j = 0; j < set.size(); ++j)
                for (int a = -1; a <= 1; ++a)
                    for (int b = -1; b <= 1; ++b)
                        for (int c = (dim == 3 ? -1 : 0); c <= (dim == 3 ? 1 : 0); ++c) {
                            const Eigen::Vector3d r =
                                set.position(i) - set.position(j) - set.box->edges * Eigen::Vector3d(a, b, c);
                            const double d = r.norm();
                            if (d / m.h > kernel.support()) continue;
                            visit(i, j, r, d);
                        }
    };
    for_pairs([&](std::size_t i, std::size_t, const Eigen::Vector3d&, double d) {
        out[i].density += m.mass * kernel.w(d / m.h, dim, m.k) / hd;
    });
    auto pi = [&](std::size_t i) {
        const double rho = out[i].density;
        return m.rho0 * m.c * m.c / m.gamma * std::pow(rho / m.rho0, m.gamma) / (rho * rho);
    };
    for_pairs([&](std::size_t i, std::size_t j, const Eigen::Vector3d& r, double d) {
        if (d == 0) return;
        const Eigen::Vector3d grad = kernel.dw(d / m.h, dim, m.k) / (hd * m.h) * r / d; // grad_i W_ij
        out[i].gradient += m.volume * grad;
        out[i].acceleration -= m.mass * (pi(i) + pi(j)) * grad;
    });
    return out;
}

ForceModel model_for(const ParticleSet& set, double h, double k)
{
    ForceModel m;
    m.h = h, m.k = k;
    m.volume = set.box->volume(set.dimension) / static_cast<double>(set.size());
    m.mass = 2.5 * m.volume, m.rho0 = 2.4, m.c = 1.3, m.gamma = 7, m.threads = 2;
    return m;
}

} // namespace

TEST_CASE("the relaxation sums agree with a brute-force sum over periodic images")
{
    for (const char* name : {"cubic_bspline", "wendland_c2"})
        for (int dim : {2, 3}) {
            CAPTURE(name);
            CAPTURE(dim);
            const Kernel kernel = shipped_kernel(name);
            const ParticleSet set = poisson_set(dim == 3 ? 300 : 200, dim, 1.0, 7);
            const double l = std::pow(1.0 / static_cast<double>(set.size()), 1.0 / dim);
            const ForceModel m = model_for(set, 1.3 * l, 1.3);
            ForceField field;
            compute_forces(kernel, set, m, field);
            const auto brute = brute_sums(kernel, set, m);
            double worst = 0;
            for (std::size_t i = 0; i < set.size(); ++i) {
                const Eigen::Vector3d g(field.gx[i], field.gy[i], field.gz[i]),
                    a(field.ax[i], field.ay[i], field.az[i]);
                worst = std::max(worst, std::abs(field.density[i] - brute[i].density) / brute[i].density);
                worst = std::max(worst, (g - brute[i].gradient).norm() / (1 + brute[i].gradient.norm()));
                worst = std::max(worst, (a - brute[i].acceleration).norm() / (1 + brute[i].acceleration.norm()));
            }
            CHECK(worst < 1e-12);
        }
}

TEST_CASE("the relaxation sums, each pair once, are the same bits on 1, 2 and 7 threads, 2D and 3D")
{
    const Kernel kernel = shipped_kernel("wendland_c2");
    for (int dim : {2, 3}) {
        CAPTURE(dim);
        // Large enough for many tiles of each colour (symmetric_pair_pass).
        const ParticleSet set = poisson_set(20000, dim, 1.0, 11);
        const double l = std::pow(1.0 / static_cast<double>(set.size()), 1.0 / dim);
        ForceModel m = model_for(set, 1.3 * l, 1.3);
        m.threads = 1;
        ForceField one;
        compute_forces(kernel, set, m, one);
        for (int threads : {2, 7}) {
            m.threads = threads;
            ForceField many;
            compute_forces(kernel, set, m, many);
            CHECK(many.density == one.density);
            CHECK(many.gx == one.gx);
            CHECK(many.gz == one.gz);
            CHECK(many.ay == one.ay);
        }
    }
}

namespace {

// The largest difference of two force fields' values, over the largest value.
double field_difference(const ForceField& a, const ForceField& b)
{
    double worst = 0, scale = 0;
    const std::vector<double> ForceField::*values[] = {&ForceField::density, &ForceField::gx, &ForceField::gy,
                                                       &ForceField::gz,      &ForceField::ax, &ForceField::ay,
                                                       &ForceField::az};
    for (const auto v : values)
        for (std::size_t i = 0; i < (a.*v).size(); ++i)
            worst = std::max(worst, std::abs((a.*v)[i] - (b.*v)[i])), scale = std::max(scale, std::abs((b.*v)[i]));
    return worst / scale;
}

// The set with every particle moved by `step` times a fixed pseudo-random vector of length up to 1, wrapped.
ParticleSet shifted(ParticleSet set, double step)
{
    for (std::size_t i = 0; i < set.size(); ++i) {
        const double t = 0.7 * static_cast<double>(i);
        set.x[i] += step * std::sin(t), set.y[i] += step * std::cos(1.3 * t), set.z[i] += step * std::sin(2.1 * t);
    }
    wrap_into_box(set);
    return set;
}

} // namespace

TEST_CASE("relax's kept pair list gives the forces of a fresh search (1e-13), and is built only where the particles "
          "move slowly enough for it to last")
{
    const Kernel kernel = shipped_kernel("wendland_c2");
    const ParticleSet start = poisson_set(3000, 3, 1.0, 5);
    const double l = std::pow(1.0 / static_cast<double>(start.size()), 1.0 / 3);
    ForceModel m = model_for(start, 1.3 * l, 1.3);
    m.skin = 0.2; // in h: kept while no particle has moved 0.1 h
    KeptPairs kept;
    ForceField field, fresh;
    // No move seen yet: the call searches, as a call with no list does (the same bits).
    compute_forces(kernel, start, m, field, &kept);
    compute_forces(kernel, start, m, fresh);
    CHECK(kept.builds == 0);
    CHECK(field.density == fresh.density);
    CHECK(field.ax == fresh.ax);
    // Moved 0.02 h at most: a list would last; it is built, and kept at the next such move.
    const ParticleSet slow = shifted(start, 0.02 * m.h / std::sqrt(3.0)), slower = shifted(slow, 0.02 * m.h / 3);
    compute_forces(kernel, slow, m, field, &kept);
    CHECK(kept.builds == 1);
    compute_forces(kernel, slower, m, field, &kept);
    compute_forces(kernel, slower, m, fresh);
    CHECK(kept.builds == 1);
    CHECK(field_difference(field, fresh) < 1e-13);
    CHECK(field_difference(field, fresh) > 0); // the list's order of the terms, not the fresh grid's
    // Moved 0.3 h since the last call: the list no longer holds, and no new one would last four calls.
    const ParticleSet fast = shifted(slower, 0.3 * m.h / std::sqrt(3.0));
    compute_forces(kernel, fast, m, field, &kept);
    compute_forces(kernel, fast, m, fresh);
    CHECK(kept.list == nullptr);
    CHECK(field.density == fresh.density);
    CHECK(field.ax == fresh.ax);
}

TEST_CASE("the pressure force on a lattice plane wave is -omega^2 times the displacement of section 10")
{
    // fcc with (111) layers in the xy plane: a wave vector along z is a threefold axis, where
    // one mode is purely longitudinal and its omega^2 is an eigenvalue of the dispersion matrix.
    const Kernel kernel = shipped_kernel("cubic_bspline");
    const Lattice fcc = load_lattice("fcc");
    const double k = 1.3, gamma = 5.0 / 3.0, amplitude = 1e-7;
    const long long cells = 8;
    ParticleSet set = lattice_block("fcc", cells);
    // b3 = 2 pi (a1 x a2) / (a3 . a1 x a2) is along z; 3/8 of it is periodic in the block of 8 cells.
    const Eigen::Vector3d a1 = fcc.basis.col(0), a2 = fcc.basis.col(1), a3 = fcc.basis.col(2);
    const Eigen::Vector3d b3 = 2 * std::numbers::pi * a1.cross(a2) / a3.dot(a1.cross(a2));
    const Eigen::Vector3d kappa = b3 * 3.0 / static_cast<double>(cells);
    REQUIRE(kappa.normalized().z() == doctest::Approx(1).epsilon(1e-12));
    for (std::size_t i = 0; i < set.size(); ++i) set.z[i] += amplitude * std::cos(kappa.dot(set.position(i)));
    wrap_into_box(set);
    ForceModel m;
    m.h = k, m.k = k, m.gamma = gamma, m.c = 1, m.threads = 2;
    m.volume = set.box->volume(3) / static_cast<double>(set.size()), m.mass = m.volume;
    // rho0 of the lattice at rest: there P / rho = c^2 / gamma.
    const ParticleSet rest = lattice_block("fcc", cells);
    ForceField field;
    ForceModel density_only = m;
    density_only.pressure = false;
    compute_forces(kernel, rest, density_only, field);
    m.rho0 = field.density[0];
    compute_forces(kernel, set, m, field);
    const Dispersion dispersion(kernel, fcc, k, gamma);
    const DispersionModes modes = dispersion.modes(kappa);
    double expected = NAN;
    for (std::size_t b = 0; b < modes.omega2.size(); ++b)
        if (modes.longitudinal[b] > 1 - 1e-9) expected = modes.omega2[b];
    REQUIRE(std::isfinite(expected));
    double worst = 0;
    for (std::size_t i = 0; i < set.size(); ++i) {
        const double phase = std::cos(kappa.dot(rest.position(i)));
        if (std::abs(phase) < 0.5) continue;
        const double measured = -field.az[i] / (amplitude * phase);
        worst = std::max(worst, std::abs(measured - expected) / std::abs(expected));
        CHECK(std::abs(field.ax[i]) < 1e-6 * std::abs(field.az[i])); // the wave is longitudinal
    }
    CHECK(worst < 1e-5);
}

TEST_CASE("undamped pressure motion keeps its energy, and a run does not depend on the thread count")
{
    const Kernel kernel = shipped_kernel("wendland_c2");
    RelaxSettings s;
    s.method = RelaxMethod::pressure;
    s.damping = 0, s.steps = 60, s.time_step = 0.05, s.gamma = 5.0 / 3.0, s.threads = 1;
    const ParticleSet start = lattice_block("sc", 6, 0.05);
    // E = sum m v^2 / 2 + sum m u(rho), u = c^2 / (gamma (gamma - 1)) (rho / rho0)^(gamma - 1): du/drho = P / rho^2.
    auto energy = [&](const RelaxState& st) {
        double e = 0;
        for (std::size_t i = 0; i < st.set.size(); ++i) {
            const double v2 = st.vx[i] * st.vx[i] + st.vy[i] * st.vy[i] + st.vz[i] * st.vz[i];
            const double u = st.model.c * st.model.c / (s.gamma * (s.gamma - 1)) *
                             std::pow(st.forces.density[i] / st.model.rho0, s.gamma - 1);
            e += st.model.mass * (v2 / 2 + u);
        }
        return e;
    };
    // Kick-drift-kick keeps the energy of these forces up to O(dt^2): halving the step quarters
    // the largest change. Forces that did not derive from E would leave a drift at any step.
    std::vector<double> drifts;
    RelaxResult one;
    for (double dt : {0.04, 0.02, 0.01}) {
        s.time_step = dt;
        std::vector<double> energies;
        one = relax_particles(kernel, start, 1.4, s,
                              [&](const RelaxState& st, const RelaxStep&) { energies.push_back(energy(st)); });
        double drift = 0;
        for (double e : energies) drift = std::max(drift, std::abs(e - energies.front()));
        drifts.push_back(drift);
    }
    CHECK(drifts[1] / drifts[0] == doctest::Approx(0.25).epsilon(0.1));
    CHECK(drifts[2] / drifts[1] == doctest::Approx(0.25).epsilon(0.1));
    CHECK(one.history.back().kinetic > 0);
    for (int threads : {2, 7}) {
        s.threads = threads;
        const RelaxResult other = relax_particles(kernel, start, 1.4, s);
        CHECK(one.state.set.x == other.state.set.x);
        CHECK(one.state.set.z == other.state.set.z);
        CHECK(one.history.back().kinetic == other.history.back().kinetic);
        CHECK(one.history.back().rms_e0 == other.history.back().rms_e0);
    }
}

TEST_CASE("relaxation refuses what it cannot do")
{
    const Kernel kernel = shipped_kernel("wendland_c2");
    ParticleSet free = poisson_set(100, 3, 1.0, 1);
    free.box.reset();
    CHECK_THROWS_AS(relax_particles(kernel, free, 0.3, RelaxSettings{}), Error);
    const ParticleSet small = lattice_block("sc", 4);
    CHECK_THROWS_AS(relax_particles(kernel, small, 1.5, RelaxSettings{}), Error); // support 3 d in a 4 d box
    CHECK_THROWS_AS(require_rectangular_box(lattice_block("fcc", 4), "a file"), Error);
}

TEST_CASE("relax settings out of range are refused, named as each front end names them")
{
    RelaxSettings bad;
    bad.time_step = 0.9;
    CHECK_THROWS_WITH_AS(check_relax_settings(bad, relax_sources(FrontEnd::command_line)),
                         "--dt 0.9: expected a number in (0, 0.5] (units of h / c)", Error);
    bad = RelaxSettings{};
    bad.max_move = 0;
    CHECK_THROWS_WITH_AS(check_relax_settings(bad, relax_sources(FrontEnd::python)),
                         "max_move = 0: expected a number in (0, 0.5] (units of h)", Error);
    bad = RelaxSettings{};
    bad.steps = 0;
    try {
        check_relax_settings(bad, relax_sources(FrontEnd::command_line));
        FAIL("steps = 0 was taken");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::usage); // an option out of range: exit 2
    }
}

TEST_CASE("a relaxed set written in SWIFT's layout and as CSV reads back")
{
    const ParticleSet set = poisson_set(500, 3, 2.0, 3);
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "sphkern-relax-files";
    std::filesystem::create_directories(folder);
    ParticleOutput output{std::vector<double>(set.size(), 0.31), 1.936492, 0.016, 1.0, "Wendland C2", 0.9};
    for (const char* name : {"glass.h5", "glass.csv"}) {
        CAPTURE(name);
        write_particle_file(folder / name, set, output);
        const ParticleSet back = read_particle_file(folder / name, {});
        REQUIRE(back.size() == set.size());
        CHECK(back.x == set.x);
        CHECK(back.z == set.z);
        CHECK(std::equal(back.h.begin(), back.h.end(), output.h.begin(), output.h.end()));
        CHECK(back.mass == ParticleValues(set.size(), output.mass));
        if (std::string(name) == "glass.h5") {
            CHECK(back.support_per_h == 1.936492);
            CHECK(back.file_kernel == "Wendland C2");
            CHECK(back.file_kernel_name == "wendland_c2");
            REQUIRE(back.box);
            CHECK(back.box->edges.diagonal() == Eigen::Vector3d(2, 2, 2));
        }
    }
    // The CSV's rows are formatted in blocks on several threads: the same bytes as on one.
    const ParticleSet larger = poisson_set(9000, 3, 2.0, 5);
    const ParticleOutput larger_output{std::vector<double>(larger.size(), 0.31), 1.936492, 0.016, 1.0, "", 0.9};
    auto csv_text = [&](int threads) {
        write_particle_file(folder / "larger.csv", larger, larger_output, threads);
        std::ifstream in(folder / "larger.csv");
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    const std::string one = csv_text(1);
    CHECK(std::count(one.begin(), one.end(), '\n') == 9002);
    CHECK(csv_text(3) == one);
    std::filesystem::remove_all(folder);
}

TEST_CASE("g(r) is 1 for a Poisson set and peaks at the nearest-neighbour distance of a lattice")
{
    const ParticleSet poisson = poisson_set(20000, 3, 1.0, 11);
    const GlassQuality random = glass_quality(poisson, 3, 30, 2);
    double mean = 0;
    for (std::size_t b = 5; b < random.rdf.g.size(); ++b) mean += random.rdf.g[b];
    mean /= static_cast<double>(random.rdf.g.size() - 5);
    CHECK(mean == doctest::Approx(1).epsilon(0.01));
    // The nearest-neighbour distance of a Poisson set in 3D: mean Gamma(4/3) (3 / (4 pi n))^(1/3).
    CHECK(random.nearest.mean ==
          doctest::Approx(std::tgamma(4.0 / 3.0) * std::cbrt(3 / (4 * std::numbers::pi))).epsilon(0.01));
    // P(nearest < 0.5 l) = 1 - exp(-4 pi / 3 0.5^3).
    CHECK(random.paired == doctest::Approx(1 - std::exp(-4 * std::numbers::pi / 3 * 0.125)).epsilon(0.05));
    const ParticleSet fcc = lattice_block("fcc", 8);
    const GlassQuality crystal = glass_quality(fcc, 2, 80, 2);
    const double l = std::cbrt(fcc.box->volume(3) / static_cast<double>(fcc.size()));
    CHECK(crystal.rdf.peak_r == doctest::Approx(1 / l).epsilon(0.02));
    CHECK(crystal.nearest.min == doctest::Approx(1 / l).epsilon(1e-12));
    CHECK(crystal.paired == 0);
}

TEST_CASE("the Poisson reference integrates W^2 as an independent midpoint rule does")
{
    for (const char* name : {"cubic_bspline", "wendland_c2", "morris_quintic"})
        for (int dim : {2, 3}) {
            CAPTURE(name);
            const Kernel kernel = shipped_kernel(name);
            const int n = 200000;
            const double dq = kernel.support() / n;
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                const double q = (i + 0.5) * dq, w = kernel.w(q, dim, 1.2);
                sum += w * w * (dim == 3 ? 4 * std::numbers::pi * q * q : 2 * std::numbers::pi * q) * dq;
            }
            CHECK(kernel_square_integral(kernel, dim, 1.2) == doctest::Approx(sum).epsilon(1e-8));
        }
}

TEST_CASE("the pairing instability in motion follows the linear verdict")
{
    // The cubic B-spline on fcc (stability of section 10): stable at k = 0.95, a longitudinal
    // mode with a growth time of about 5 d/c at k = 1.8. The Wendland C2 kernel at k = 2.2
    // (N_H = 505) has only a slow transverse mode (29 d/c), and must not pair.
    const Lattice fcc = load_lattice("fcc");
    PairingRequest request;
    request.threads = 2;
    request.k_min = request.k_max = 0.95;
    const auto stable = pairing_motion(shipped_kernel("cubic_bspline"), fcc, request).front();
    CHECK(stable.verdict == Verdict::stable);
    CHECK(stable.outcome == "returned");
    CHECK(stable.rms_end < 0.2 * stable.rms_start);
    CHECK(stable.paired_end == 0);
    // Linear motion: the RMS displacement follows every block mode damped from the noise.
    CHECK(stable.rms_end / stable.rms_start == doctest::Approx(stable.predicted_factor).epsilon(0.1));
    // Every pass, the block's draw and the RMS sums included, is the same on any thread count.
    request.threads = 3;
    const auto stable_on_3 = pairing_motion(shipped_kernel("cubic_bspline"), fcc, request).front();
    CHECK(stable_on_3.rms_start == stable.rms_start);
    CHECK(stable_on_3.rms_end == stable.rms_end);
    CHECK(stable_on_3.rms_max == stable.rms_max);
    CHECK(stable_on_3.measured_rate == stable.measured_rate);
    request.threads = 2;
    request.k_min = request.k_max = 1.8;
    const auto pairing = pairing_motion(shipped_kernel("cubic_bspline"), fcc, request).front();
    CHECK(pairing.verdict == Verdict::unstable);
    CHECK(pairing.kind == "longitudinal");
    CHECK(pairing.outcome == "paired");
    CHECK(pairing.paired_end > 0.5);
    // The growth measured over the linear stage is the damped linear rate, up to the other modes the noise holds.
    CHECK(pairing.measured_rate == doctest::Approx(pairing.predicted_rate).epsilon(0.25));
    request.k_min = request.k_max = 2.2;
    const auto wendland = pairing_motion(shipped_kernel("wendland_c2"), fcc, request).front();
    CHECK(wendland.kind == "transverse");
    CHECK(wendland.paired_end == 0);
    CHECK(wendland.rms_end / wendland.rms_start == doctest::Approx(wendland.predicted_factor).epsilon(0.05));
}

TEST_CASE("a 3D glass of 10^4 particles at N_H = 100 is far more uniform than a Poisson set")
{
    const Kernel kernel = shipped_kernel("wendland_c2");
    const ParticleSet start = poisson_set(10000, 3, 1.0, 5);
    RelaxSettings s;
    s.steps = 60, s.threads = 2;
    const double l = std::cbrt(1.0 / 10000.0);
    const double eta = eta_for_neighbour_number(100, kernel.support(), 3);
    const RelaxResult run = relax_particles(kernel, start, eta * l, s);
    const double poisson = poisson_rms_e0(kernel, 3, eta, eta, 10000);
    CHECK(run.history.front().rms_e0 == doctest::Approx(poisson).epsilon(0.05)); // the start is a Poisson set
    CHECK(run.history.back().rms_e0 < 0.05 * poisson);
    const GlassQuality q = glass_quality(run.state.set, 3, 60, 2);
    CHECK(q.paired == 0);
    CHECK(q.rdf.peak < 2.5); // a glass: one soft first shell, no lattice peaks
}
