// sphkern.run and sphkern.studies: a study into its results folder through the one study
// runner the command line uses, and the shipped studies.
#include "command_docstrings.hpp"
#include "commands_binding.hpp"
#include "module_support.hpp"
#include "setting_keywords.hpp"

#include "requests/studies_request.hpp"
#include "study/reproduce.hpp"
#include "study/study_run.hpp"
#include "support/error.hpp"
#include "support/process/interruption.hpp"

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <string>

namespace py = pybind11;

namespace sphkern {

namespace {

py::dict run_command(const std::optional<std::string>& study, const std::optional<std::string>& output, bool no_plots,
                     const std::string& format, bool force, const std::optional<std::string>& reproduce)
{
    py::dict out;
    if (reproduce) {
        if (study || output || force)
            fail_input(
                "reproduce: runs the study the results file records; expected no study, output or force beside it");
        Reproduction outcome;
        {
            py::gil_scoped_release unlocked;
            std::lock_guard lock(registry_mutex());
            outcome = reproduce_study(*reproduce, registry());
        }
        out["agreed"] = outcome.agreed;
        out["report"] = outcome.text;
        return out;
    }
    const StudyRunRequest request{study.value_or(""), output.value_or(""), !no_plots, format, force};
    StudyRun done;
    {
        py::gil_scoped_release unlocked;
        std::lock_guard lock(registry_mutex());
        done = run_study_folder(request, {"format"}, []() -> KernelRegistry& { return registry(); });
    }
    // As the command line warns: the folder is complete, without the figures.
    if (done.gnuplot_missing &&
        PyErr_WarnEx(PyExc_RuntimeWarning, "gnuplot not found on PATH: figures skipped", 1) != 0)
        throw py::error_already_set();
    out["folder"] = std::filesystem::absolute(done.folder).lexically_normal().string();
    out["cases"] = done.cases;
    out["figures"] = done.figures;
    out["summary"] = done.summary;
    return out;
}

} // namespace

void bind_studies(py::module_& m)
{
    const py::call_guard<InterruptScope> guard;
    const SettingKeywords run_keywords("run");
    m.def("run", &run_command, run_keywords("study"), run_keywords("output"), py::kw_only(), run_keywords("no_plots"),
          run_keywords("format"), run_keywords("force"), run_keywords("reproduce"), doc::run, guard);
    m.def(
        "studies", []() -> py::list { return to_python(studies_listing()); }, doc::studies, guard);
    m.def("settings", &settings_listing, py::arg("command"), doc::settings, guard);
}

} // namespace sphkern
