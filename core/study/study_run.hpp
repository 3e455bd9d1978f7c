// A study run into its results folder (`sphkern run`, Python's run): the study file from a
// path or a shipped study's name, the folder complete or not at all, the figures drawn
// where gnuplot is found.
#pragma once

#include "kernels/kernel_registry.hpp"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sphkern {

struct StudyRunRequest {
    std::string study;           // a study file, or a shipped study's name; empty: the paper's
    std::string output;          // the results folder; empty: sphkern-results/<study name>
    bool plots = true;           // draw the figures the study asks for
    std::string formats = "svg"; // the figures' formats, comma-separated
    bool force = false;          // replace a results folder sphkern wrote
};

// How the front end names the formats in its errors ("--format", "format").
struct StudyRunSources {
    std::string format;
};

// The study file: a path as given, or a shipped study's (an unknown name refused, with the shipped names).
std::filesystem::path study_file(const std::string& study);

struct StudyRun {
    std::filesystem::path folder; // the results folder, written
    std::size_t cases = 0;
    std::vector<std::string> figures; // drawn into it
    bool gnuplot_missing = false;     // figures asked for, none drawn
    std::string summary;              // the replication table, or the verdicts (markdown)
};

// `kernels` gives the registry once the study is read and its folder can be made (the plugins
// are looked for then, after the study's own errors).
StudyRun run_study_folder(const StudyRunRequest& request, const StudyRunSources& sources,
                          const std::function<KernelRegistry&()>& kernels);

} // namespace sphkern
