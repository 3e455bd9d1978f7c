#include "requests/particles_report.hpp"

#include "support/io/chunked_writer.hpp"
#include "support/io/vtk_points.hpp"
#include "support/io/vtk_xml.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <stdexcept>

namespace sphkern {

namespace {

nlohmann::json vector_json(const Eigen::Vector3d& v, int dim)
{
    return dim == 2 ? nlohmann::json{v.x(), v.y()} : nlohmann::json{v.x(), v.y(), v.z()};
}

// A sweep as the curves of the literature: one row per eta (N_H), the RMS of each error.
void print_sweep_table(std::FILE* out, const ParticleAnswer& answer)
{
    fmt::print(out, "\n{:>9} {:>9} {:>10} {:>12} {:>12} {:>12} {:>14} {:>12} {:>12}\n", "h/l", "N_H", "neighbours",
               "mean e0", "rms e0", "rms eps_gradp", "rms gradp_sum", "rms |e1|", "rms ||E||_F");
    for (const auto& p : answer.points)
        fmt::print(out, "{:>9.4f} {:>9.3f} {:>10.2f} {:>12.4e} {:>12.4e} {:>12.4e} {:>14.4e} {:>12.4e} {:>12.4e}\n",
                   p.eta, p.nh, p.mean_neighbours, p.statistic("e0").mean, p.statistic("e0").rms,
                   p.statistic("eps_gradp").rms, p.statistic("eps_gradp_sum").rms, p.statistic("|e1|").rms,
                   p.statistic("||E||_F").rms);
}

} // namespace

nlohmann::json summary_json(const Summary& s)
{
    return {{"mean", s.mean}, {"std", s.std}, {"rms", s.rms}, {"min", s.min},
            {"max", s.max},   {"p1", s.p1},   {"p50", s.p50}, {"p99", s.p99}};
}

nlohmann::json phases_json(const PhaseTimes& phases)
{
    nlohmann::json document = nlohmann::json::object();
    for (const auto& [name, seconds] : phases.phases()) document[name] = seconds;
    return document;
}

nlohmann::json point_json(const ParticlePoint& p)
{
    nlohmann::json statistics = nlohmann::json::object();
    for (const auto& [name, s] : p.statistics) statistics[name] = summary_json(s);
    nlohmann::json point = {{"h_over_l", p.eta},
                            {"nh", p.nh},
                            {"h_min", p.h_min},
                            {"h_max", p.h_max},
                            {"mean_neighbours", p.mean_neighbours},
                            {"pairs", p.pairs},
                            {"seconds", p.seconds},
                            {"cpu_seconds", p.cpu_seconds},
                            {"statistics", statistics}};
    if (!p.histograms.empty()) {
        nlohmann::json histograms = nlohmann::json::object();
        for (const auto& [name, h] : p.histograms)
            histograms[name] = {{"min", h.lo}, {"max", h.hi}, {"counts", h.counts}};
        point["histograms"] = histograms;
    }
    return point;
}

nlohmann::json particle_answer_json(const Kernel& kernel, const ParticleSet& set, const ParticleAnswer& answer,
                                    const ParticleArguments& asked)
{
    nlohmann::json source = {{"name", set.name},
                             {"particles", answer.particles},
                             {"dimension", set.dimension},
                             {"periodic", set.box.has_value()}};
    if (set.neighbours_only) source["neighbours_only"] = set.neighbours_only;
    if (set.box) {
        nlohmann::json edges = nlohmann::json::array();
        for (int a = 0; a < set.dimension; ++a) edges.push_back(vector_json(set.box->edges.col(a), set.dimension));
        source["box"] = edges;
    }
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : answer.points) points.push_back(point_json(p));
    nlohmann::json document = {{"kernel", kernel.label()},
                               {"support", kernel.support()},
                               {"source", source},
                               {"volume", volume_model_name(answer.volume)},
                               {"mean_volume", answer.mean_volume},
                               {"rho0", answer.rho0},
                               {"gravity", vector_json(answer.gravity, set.dimension)},
                               {"threads", answer.threads}};
    document["phases"] = phases_json(answer.phases);
    if (answer.points.size() == 1) document.update(point_json(answer.points[0]));
    else document["sweep"] = points;
    if (asked.code) document["code"] = code_answer_json(*asked.code);
    if (asked.stored_h_code) document["code"] = stored_code_json(*asked.stored_h_code, kernel, set.dimension);
    return document;
}

void print_particle_answer(std::FILE* out, const Kernel& kernel, const ParticleSet& set, const ParticleAnswer& answer,
                           const ParticleArguments& asked)
{
    fmt::print(out, "{} on {}: {} particles{} in {}D, {}, volumes {} (mean {:.6g}), gravity ({:.4g}, {:.4g}{})\n",
               kernel.label(), set.name, answer.particles,
               set.neighbours_only ? fmt::format(" (and {} neighbours only)", set.neighbours_only) : "", set.dimension,
               set.box ? "periodic box" : "free (no box)", volume_model_name(answer.volume), answer.mean_volume,
               answer.gravity.x(), answer.gravity.y(),
               set.dimension == 3 ? fmt::format(", {:.4g}", answer.gravity.z()) : "");
    if (asked.code) fmt::print(out, "{}\n", code_answer_text(*asked.code));
    if (asked.stored_h_code) fmt::print(out, "{}\n", stored_code_text(*asked.stored_h_code, kernel, set.dimension));
    if (answer.points.size() > 1) {
        print_sweep_table(out, answer);
        return;
    }
    for (const auto& p : answer.points) {
        fmt::print(
            out,
            "\nh/l = {:.6g} (h over the mean spacing), N_H = {:.6g}, h in [{:.6g}, {:.6g}]: {:.2f} neighbours on "
            "average, {} pairs in {:.3f} s\n",
            p.eta, p.nh, p.h_min, p.h_max, p.mean_neighbours, p.pairs, p.seconds);
        fmt::print(out, "{:<14} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}\n", "measure", "mean", "std",
                   "rms", "min", "p1", "p50", "p99", "max");
        for (const auto& [name, s] : p.statistics)
            fmt::print(out, "{:<14} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e}\n",
                       name, s.mean, s.std, s.rms, s.min, s.p1, s.p50, s.p99, s.max);
        for (const auto& [name, h] : p.histograms) {
            fmt::print(out, "histogram of {} over [{:.6g}, {:.6g}]:", name, h.lo, h.hi);
            for (auto c : h.counts) fmt::print(out, " {}", c);
            fmt::print(out, "\n");
        }
    }
}

namespace {

// One particle's CSV row: the one format of the whole set in memory and of a set in slabs.
struct CsvRow {
    std::uint64_t id;
    double x, y, z, h, volume;
    long long neighbours;
    double e0, eps_rho, eps_gradp;
    std::array<double, 3> e1, m1;
};

void format_row(fmt::memory_buffer& row, const CsvRow& r, bool three)
{
    auto to = std::back_inserter(row);
    fmt::format_to(to, "{},{},{},", r.id, r.x, r.y);
    if (three) fmt::format_to(to, "{},", r.z);
    fmt::format_to(to, "{},{},{},{},{},{},{},{},", r.h, r.volume, r.neighbours, r.e0, r.eps_rho, r.eps_gradp, r.e1[0],
                   r.e1[1]);
    if (three) fmt::format_to(to, "{},", r.e1[2]);
    fmt::format_to(to, "{},{}", r.m1[0], r.m1[1]);
    if (three) fmt::format_to(to, ",{}", r.m1[2]);
    fmt::format_to(to, "\n");
}

void print_csv_header(ChunkedWriter& out, bool three)
{
    out.print("id,x,y,{}h,volume,neighbours,e0,eps_rho,eps_gradp,e1_x,e1_y,{}m1_x,m1_y{}\n", three ? "z," : "",
              three ? "e1_z," : "", three ? ",m1_z" : "");
}

} // namespace

// The per-particle values in the shortest form that reads back to the same double.
void write_particle_csv(std::ostream& stream, const ParticleSet& set, const ParticleAnswer& answer)
{
    const auto& m = *answer.measures;
    const bool three = set.dimension == 3;
    ChunkedWriter out(stream);
    print_csv_header(out, three);
    out.rows(set.measured(), answer.threads, [&](fmt::memory_buffer& row, std::size_t i) {
        const MeasureRecord& r = m.scalars[i];
        format_row(row,
                   {i, set.x[i], set.y[i], set.z[i], answer.h[i], answer.volumes[i], r.neighbours, r.e0,
                    m.eps_rho_of(i), r.eps_gradp, m.e1[i], m.m1[i]},
                   three);
    });
}

ParticleCsvRows::ParticleCsvRows(std::ostream& out, int dimension, int threads)
    : out_(out), three_(dimension == 3), threads_(threads)
{
    print_csv_header(out_, three_);
}

void ParticleCsvRows::write(const MeasuredRows& r)
{
    out_.rows(r.count, threads_, [&](fmt::memory_buffer& row, std::size_t k) {
        format_row(row,
                   {r.begin + k,
                    r.x[k],
                    r.y[k],
                    r.z[k],
                    r.h[k],
                    r.volume[k],
                    static_cast<long long>(r.neighbours[k]),
                    r.e0[k],
                    r.eps_rho[k],
                    r.eps_gradp[k],
                    {r.e1[0][k], r.e1[1][k], r.e1[2][k]},
                    {r.m1[0][k], r.m1[1][k], r.m1[2][k]}},
                   three_);
    });
}

void write_particle_vtk(std::ostream& stream, const ParticleSet& set, const ParticleAnswer& answer)
{
    const auto& m = *answer.measures;
    const std::size_t n = set.measured(); // the neighbours-only particles have no measures
    const int threads = answer.threads;
    ChunkedWriter out(stream);
    write_vtk_points(out, "sphkern particles: consistency errors per particle", n, set.x.data(), set.y.data(),
                     set.z.data(), threads);
    auto scalars = [&](const char* name, auto value) {
        out.print("SCALARS {} double 1\nLOOKUP_TABLE default\n", name);
        out.rows(n, threads, [&](fmt::memory_buffer& row, std::size_t i) {
            fmt::format_to(std::back_inserter(row), "{}\n", static_cast<double>(value(i)));
        });
    };
    scalars("id", [](std::size_t i) { return i; });
    scalars("h", [&](std::size_t i) { return answer.h[i]; });
    scalars("volume", [&](std::size_t i) { return answer.volumes[i]; });
    scalars("neighbours", [&](std::size_t i) { return m.scalars[i].neighbours; });
    scalars("e0", [&](std::size_t i) { return m.scalars[i].e0; });
    scalars("eps_rho", [&](std::size_t i) { return m.eps_rho_of(i); });
    scalars("eps_gradp", [&](std::size_t i) { return m.scalars[i].eps_gradp; });
    for (const auto& [name, field] : {std::pair{"e1", &m.e1}, std::pair{"m1", &m.m1}}) {
        out.print("VECTORS {} double\n", name);
        out.rows(n, threads, [&](fmt::memory_buffer& row, std::size_t i) {
            const auto& v = (*field)[i];
            fmt::format_to(std::back_inserter(row), "{} {} {}\n", v[0], v[1], v[2]);
        });
    }
}

void write_particle_vtu(std::ostream& out, const ParticleSet& set, const ParticleAnswer& answer)
{
    const auto& m = *answer.measures;
    const std::size_t n = set.measured(); // the neighbours-only particles have no measures
    const bool three = set.dimension == 3;
    const VtuPoints points{{set.x.data(), n},
                           {set.y.data(), n},
                           three ? std::span<const double>(set.z.data(), n) : std::span<const double>{}};
    auto scalar = [](const char* name, auto value) {
        return VtuArray{name, 1, [value](std::size_t i, int) { return static_cast<double>(value(i)); }};
    };
    // The CSV's e1_x, e1_y[, e1_z] as one vector.
    auto vector = [three](const char* name, const auto& field) {
        return VtuArray{name, 3, [&field, three](std::size_t i, int c) { return c < 2 || three ? field[i][c] : 0.0; }};
    };
    write_vtu(out, points,
              {scalar("id", [](std::size_t i) { return i; }), scalar("h", [&](std::size_t i) { return answer.h[i]; }),
               scalar("volume", [&](std::size_t i) { return answer.volumes[i]; }),
               scalar("neighbours", [&](std::size_t i) { return m.scalars[i].neighbours; }),
               scalar("e0", [&](std::size_t i) { return m.scalars[i].e0; }),
               scalar("eps_rho", [&](std::size_t i) { return m.eps_rho_of(i); }),
               scalar("eps_gradp", [&](std::size_t i) { return m.scalars[i].eps_gradp; }), vector("e1", m.e1),
               vector("m1", m.m1)});
}

} // namespace sphkern
