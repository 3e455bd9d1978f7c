// A run's snapshots measured with one set of settings (`sphkern particles KERNEL FILE FILE ...`
// or a folder): which files make the series, in which order, and what is reported of each.
#pragma once

#include "particles/particle_analysis.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace sphkern {

// One snapshot of a series, measured: what a run on the file alone prints as JSON, and the
// statistics the series' table and figure show.
struct SeriesSnapshot {
    std::string file;
    std::optional<double> time; // as the file's header gives it
    std::size_t particles = 0;
    ParticlePoint point;
    std::string answer;    // the JSON document of a run on the file alone, as text
    std::size_t given = 0; // its place among the files given
};

// The files named, each folder replaced by the particle files in it (by name): a code's own
// dumps (HDF5, GADGET binary, Phantom) where it holds any, else its CSV and VTK files; a
// snapshot in parts (BASE.0, BASE.1, ...) once, by its first part. Error(input) for a folder
// without particle files.
std::vector<std::string> series_files(const std::vector<std::string>& named);

// Error(input) naming both files where `next` cannot follow `first` in one series: another
// dimension, or a file format that is another code's.
void check_series_member(const std::string& first, const ParticleSet& first_set, const std::string& next,
                         const ParticleSet& next_set);

// Sorts by the headers' times where every snapshot has one (ties keep file order); else keeps
// file order. True if sorted by time. Error(input) naming the file whose time is not finite.
bool order_series(std::vector<SeriesSnapshot>& series);

// {"series": [{"file", "time", ...the run's own answer}], "ordered_by": "time" | "file order"}.
nlohmann::json series_json(const std::vector<SeriesSnapshot>& series, bool by_time);
// One row per snapshot: its time, particles, neighbours and the percentiles of e0, eps_rho, eps_gradp.
void print_series(std::FILE* out, const std::string& kernel, const std::vector<SeriesSnapshot>& series, bool by_time);

// A gnuplot script (no terminal, no output) of the errors against time (file order without
// times): for e0, eps_rho and eps_gradp the median and the band from p1 to p99, one panel each.
std::string series_figure_script(const std::vector<SeriesSnapshot>& series, bool by_time);

// The per-snapshot output of a series: "errors.csv" and "run/snap_042.hdf5" give
// "errors_snap_042.csv" (the snapshot's name without a particle file's extension).
std::string snapshot_output(const std::string& output, const std::string& snapshot, const std::string& extension);

} // namespace sphkern
