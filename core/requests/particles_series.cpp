#include "requests/particles_series.hpp"

#include "particles/formats/particle_files.hpp"
#include "support/error.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

namespace sphkern {

namespace {

namespace fs = std::filesystem;

bool is_code_dump(ParticleFileFormat format)
{
    return format == ParticleFileFormat::hdf5 || format == ParticleFileFormat::gadget_binary ||
           format == ParticleFileFormat::phantom_dump;
}

// BASE.N[.hdf5] with N > 0 beside BASE.0[.hdf5]: a later part of a snapshot in parts.
bool later_part(const fs::path& file, const std::set<std::string>& names)
{
    static const std::regex part(R"((.*)\.([0-9]+)(\.hdf5|\.h5)?)");
    std::smatch m;
    const std::string name = file.filename().string();
    if (!std::regex_match(name, m, part) || std::stoull(m[2].str().substr(0, 18)) == 0) return false;
    return names.count(m[1].str() + ".0" + m[3].str()) > 0;
}

std::vector<std::string> folder_files(const fs::path& folder)
{
    std::vector<fs::path> files;
    std::set<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        if (!entry.is_regular_file(ec)) continue;
        files.push_back(entry.path());
        names.insert(entry.path().filename().string());
    }
    if (ec)
        fail_input(fmt::format("{}: the folder cannot be listed ({}); expected a folder of snapshots", folder.string(),
                               ec.message()));
    std::sort(files.begin(), files.end());
    std::vector<std::string> dumps, tables;
    for (const auto& file : files) {
        if (later_part(file, names)) continue;
        const auto format = particle_file_format(file);
        if (!format) continue;
        (is_code_dump(*format) ? dumps : tables).push_back(file.string());
    }
    if (dumps.empty() && tables.empty())
        fail_input(
            fmt::format("{}: the folder holds no particle file; expected snapshots (HDF5, GADGET binary, Phantom "
                        "dumps, CSV or VTK)",
                        folder.string()));
    return dumps.empty() ? tables : dumps;
}

std::string format_of(const std::string& file, const ParticleSet& set)
{
    const auto format = particle_file_format(file);
    if (!format) return "unknown";
    switch (*format) {
    case ParticleFileFormat::hdf5:
        if (!set.arrays.empty()) return "PySPH HDF5";
        return set.support_per_h == 1 ? "GADGET HDF5" : "SWIFT HDF5";
    case ParticleFileFormat::csv: return "CSV";
    case ParticleFileFormat::vtk: return "VTK";
    case ParticleFileFormat::gadget_binary: return "GADGET binary";
    case ParticleFileFormat::phantom_dump: return "Phantom dump";
    }
    return "unknown";
}

std::string time_text(const std::optional<double>& time) { return time ? fmt::format("{:.6g}", *time) : "-"; }

} // namespace

std::vector<std::string> series_files(const std::vector<std::string>& named)
{
    std::vector<std::string> files;
    for (const auto& name : named) {
        std::error_code ec;
        if (fs::is_directory(name, ec)) {
            const auto more = folder_files(name);
            files.insert(files.end(), more.begin(), more.end());
        } else {
            files.push_back(name);
        }
    }
    return files;
}

void check_series_member(const std::string& first, const ParticleSet& first_set, const std::string& next,
                         const ParticleSet& next_set)
{
    if (next_set.dimension != first_set.dimension)
        fail_input(fmt::format("{} is {}D but {} is {}D; expected the snapshots of one run, in one dimension", next,
                               next_set.dimension, first, first_set.dimension));
    const std::string a = format_of(first, first_set), b = format_of(next, next_set);
    if (a != b)
        fail_input(
            fmt::format("{} is a {} file but {} is a {} file; expected the snapshots of one run, written by one code",
                        next, b, first, a));
}

bool order_series(std::vector<SeriesSnapshot>& series)
{
    for (const auto& s : series)
        if (s.time && !std::isfinite(*s.time))
            fail_input(fmt::format("{}: its header's time is {}; expected a finite number", s.file, *s.time));
    const bool by_time =
        std::all_of(series.begin(), series.end(), [](const SeriesSnapshot& s) { return s.time.has_value(); });
    if (by_time)
        std::stable_sort(series.begin(), series.end(),
                         [](const SeriesSnapshot& a, const SeriesSnapshot& b) { return *a.time < *b.time; });
    return by_time;
}

nlohmann::json series_json(const std::vector<SeriesSnapshot>& series, bool by_time)
{
    nlohmann::json entries = nlohmann::json::array();
    for (const auto& s : series) {
        nlohmann::json entry = {{"file", s.file}, {"time", s.time ? nlohmann::json(*s.time) : nlohmann::json()}};
        entry.update(nlohmann::json::parse(s.answer));
        entries.push_back(entry);
    }
    return {{"ordered_by", by_time ? "time" : "file order"}, {"snapshots", series.size()}, {"series", entries}};
}

void print_series(std::FILE* out, const std::string& kernel, const std::vector<SeriesSnapshot>& series, bool by_time)
{
    fmt::print(out, "{} on a series of {} snapshots, ordered by {}\n", kernel, series.size(),
               by_time ? "the time in their headers" : "file order (not every header gives a time)");
    fmt::print(out, "\n{:>12} {:>10} {:>10} {:>11} {:>11} {:>11} {:>11} {:>11} {:>11}  {}\n", "time", "particles",
               "neighbours", "e0 p50", "e0 p99", "eps_rho p1", "eps_rho p99", "gradp p1", "gradp p99", "file");
    for (const auto& s : series) {
        const auto& e0 = s.point.statistic("e0");
        const auto& rho = s.point.statistic("eps_rho");
        const auto& gradp = s.point.statistic("eps_gradp");
        fmt::print(out, "{:>12} {:>10} {:>10.2f} {:>11.4e} {:>11.4e} {:>11.4e} {:>11.4e} {:>11.4e} {:>11.4e}  {}\n",
                   time_text(s.time), s.particles, s.point.mean_neighbours, e0.p50, e0.p99, rho.p1, rho.p99, gradp.p1,
                   gradp.p99, s.file);
    }
}

std::string series_figure_script(const std::vector<SeriesSnapshot>& series, bool by_time)
{
    static const char* measures[] = {"e0", "eps_rho", "eps_gradp"};
    std::string script = "$series << EOD\n";
    for (std::size_t i = 0; i < series.size(); ++i) {
        script += fmt::format("{:.17g}", by_time ? *series[i].time : static_cast<double>(i + 1));
        for (const char* name : measures) {
            const Summary& s = series[i].point.statistic(name);
            script += fmt::format(" {:.17g} {:.17g} {:.17g}", s.p1, s.p50, s.p99);
        }
        script += "\n";
    }
    script += "EOD\nset multiplot layout 3,1\nset grid\nset key top left noenhanced\n";
    for (std::size_t m = 0; m < 3; ++m) {
        const std::size_t c = 2 + 3 * m; // the columns of p1, p50 and p99
        script += fmt::format("set ylabel '{}' noenhanced\n", measures[m]);
        script += m == 2 ? fmt::format("set xlabel \"{}\"\n",
                                       by_time ? "time (from the snapshots' headers)" : "snapshot (file order)")
                         : "";
        script +=
            fmt::format("plot $series using 1:{}:{} with filledcurves fc '#1f77b4' fs transparent solid 0.25 "
                        "title 'p1 to p99', '' using 1:{} with linespoints pt 7 ps 0.6 lc '#1f77b4' title 'median'\n",
                        c, c + 2, c + 1);
        script += m == 0 ? "unset key\n" : ""; // one legend for the figure
    }
    return script + "unset multiplot\n";
}

std::string snapshot_output(const std::string& output, const std::string& snapshot, const std::string& extension)
{
    const fs::path out(output), in(snapshot);
    const std::string ext = in.extension().string();
    const bool table_extension = ext == ".hdf5" || ext == ".h5" || ext == ".csv" || ext == ".vtk";
    const std::string name = table_extension ? in.stem().string() : in.filename().string();
    return (out.parent_path() / (out.stem().string() + "_" + name + extension)).string();
}

} // namespace sphkern
