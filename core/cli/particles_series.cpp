// `sphkern particles KERNEL FILE FILE ...` (or a folder): every snapshot of a run measured with
// the same settings, each exactly as a run on that file alone, reported in the order of time.
#include "cli/particles_command.hpp"

#include "particles/sources/particle_source.hpp"
#include "requests/particles_report.hpp"
#include "requests/particles_series.hpp"
#include "requests/settings/command_settings.hpp"
#include "study/series_figure.hpp"
#include "support/error.hpp"
#include "support/io/atomic_file.hpp"
#include "support/io/results_output.hpp"
#include "support/io/vtk_xml.hpp"
#include "support/process/progress.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>

namespace sphkern::cli {

namespace {

// What a series' first snapshot fixes for the rest (no coordinates kept).
ParticleSet outline_of(const ParticleSet& set)
{
    ParticleSet outline;
    outline.name = set.name;
    outline.dimension = set.dimension;
    outline.support_per_h = set.support_per_h;
    outline.arrays = set.arrays;
    return outline;
}

// NAME.pvd: one entry per snapshot measured, at its time (its place in the series without times).
void write_collection(const std::string& pvd, const std::vector<SeriesSnapshot>& series, bool by_time)
{
    std::vector<PvdEntry> entries;
    for (std::size_t k = 0; k < series.size(); ++k)
        entries.push_back({by_time ? *series[k].time : static_cast<double>(k),
                           std::filesystem::path(snapshot_output(pvd, series[k].file, ".vtu")).filename().string()});
    write_file_atomically(pvd, [&](std::ostream& out) { write_pvd(out, entries); });
}

std::vector<std::string> checked_series_files(const ParticlesOptions& o)
{
    std::vector<std::string> named{o.source};
    named.insert(named.end(), o.more.begin(), o.more.end());
    const auto files = series_files(named);
    for (const auto& file : files)
        if (source_kind(file) != SourceKind::file)
            throw Error(ExitCode::usage,
                        fmt::format("{}: a series is made of particle files (and folders of them); expected "
                                    "no lattice or poisson source among them",
                                    file));
    if (!o.h_over_l_range.empty() || !o.nh_range.empty())
        throw Error(ExitCode::usage,
                    "--h-over-l-range and --nh-range sweep one file; a series measures each snapshot at "
                    "one h (give --h-over-l, --nh or --code)");
    if (!o.vtk.empty() && std::filesystem::path(o.vtk).extension() != ".pvd")
        throw Error(ExitCode::usage, fmt::format("--vtk {}: a series is written as a ParaView collection; expected "
                                                 "NAME.pvd (with NAME_<snapshot>.vtu beside it)",
                                                 o.vtk));
    return files;
}

// The files a series writes, each checked against every file it reads.
std::vector<OutputTarget> series_outputs(const ParticlesOptions& o, const std::vector<std::string>& files)
{
    std::vector<OutputTarget> outputs;
    if (!o.csv.empty())
        for (const auto& file : files) outputs.push_back({"--csv", snapshot_output(o.csv, file, ".csv")});
    if (!o.vtk.empty()) {
        for (const auto& file : files) outputs.push_back({"--vtk", snapshot_output(o.vtk, file, ".vtu")});
        outputs.push_back({"--vtk", o.vtk});
    }
    if (!o.plot.empty()) {
        series_figure_format(o.plot, "--plot");
        outputs.push_back({"--plot", o.plot});
    }
    std::vector<std::string> inputs;
    for (const auto& file : files) {
        const auto more = read_inputs(file, o.kernel, o.plugins);
        inputs.insert(inputs.end(), more.begin(), more.end());
    }
    check_output_targets(outputs, inputs);
    return outputs;
}

// An error of one snapshot, naming it where the message does not.
Error snapshot_error(const Error& e, const std::string& file, std::size_t index, std::size_t count)
{
    const std::string message = e.what();
    if (message.find(file) != std::string::npos) return e;
    return Error(e.code(), fmt::format("{} (snapshot {} of {}): {}", file, index + 1, count, message));
}

nlohmann::json series_inputs(const ParticlesOptions& o, const Kernel& kernel, const std::vector<SeriesSnapshot>& series)
{
    nlohmann::json inputs, files = nlohmann::json::array();
    for (const auto& s : series) {
        SourceOptions one = o;
        one.source = s.file;
        nlohmann::json each = source_inputs(one, kernel);
        files.push_back(each["particles"]);
        if (inputs.is_null()) inputs = each;
    }
    inputs["particles"] = files;
    return inputs;
}

} // namespace

int measure_series(const ParticlesOptions& o, const Kernel& kernel)
{
    const auto files = checked_series_files(o);
    const auto outputs = series_outputs(o, files);
    std::vector<SeriesSnapshot> series;
    nlohmann::json failed = nlohmann::json::array();
    std::optional<ParticleSet> first;
    Progress progress("snapshots", files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        const std::string& file = files[i];
        ParticlesOptions one = o;
        one.source = file;
        one.more.clear();
        try {
            const auto check = [&](const ParticleSet& set) {
                if (first) check_series_member(first->name, *first, file, set);
                else first = outline_of(set);
            };
            const std::string csv = o.csv.empty() ? std::string() : snapshot_output(o.csv, file, ".csv");
            const std::string vtu = o.vtk.empty() ? std::string() : snapshot_output(o.vtk, file, ".vtu");
            const Measured m = measure_source(one, kernel, outputs, csv, vtu, check);
            series.push_back({file, m.set.time, m.answer.particles, m.answer.points.front(),
                              particle_answer_json(kernel, m.set, m.answer, m.arguments).dump()});
        } catch (const Error& e) {
            // A bad snapshot may be skipped; the settings, the outputs and an interrupt stop every one.
            if (!o.keep_going || e.code() != ExitCode::input) throw snapshot_error(e, file, i, files.size());
            spdlog::warn("{}",
                         spelled_message(FrontEnd::command_line, snapshot_error(e, file, i, files.size()).what()));
            failed.push_back({{"file", file}, {"error", spelled_message(FrontEnd::command_line, e.what())}});
        }
        progress.step(file);
    }
    if (series.empty())
        throw Error(ExitCode::input,
                    fmt::format("none of the {} snapshots could be measured; expected at least one", files.size()));
    const bool by_time = order_series(series);
    if (!o.plot.empty()) draw_series_figure(o.plot, "--plot", series_figure_script(series, by_time));
    if (!o.vtk.empty()) write_collection(o.vtk, series, by_time);
    if (o.json) {
        nlohmann::json document = {{"kernel", kernel.label()}};
        document.update(series_json(series, by_time));
        if (!failed.empty()) document["failed"] = failed;
        print_json(document, series_inputs(o, kernel, series));
    } else {
        print_series(results_file(), kernel.label(), series, by_time);
        for (const auto& f : failed)
            fmt::print(results_file(), "skipped {}: {}\n", f["file"].get<std::string>(), f["error"].get<std::string>());
    }
    return 0;
}

} // namespace sphkern::cli
