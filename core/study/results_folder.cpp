#include "study/results_folder.hpp"

#include "study/report.hpp"
#include "study/results_writer.hpp"
#include "support/io/chunked_writer.hpp"
#include "support/io/install_paths.hpp"

#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>

namespace sphkern {

namespace {

void write_curves_csv(std::ostream& out, const StudyResults& results)
{
    ChunkedWriter w(out);
    w.text("lattice,mode,kernel,volume_coefficient,a_p,k,eps_rho,eps_gradp,lateral,neighbours\n");
    for (const auto& c : results.cases)
        for (const auto& [k, v] : c.curve)
            w.print("{},{},\"{}\",{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{}\n", c.lattice, c.mode, c.kernel_label,
                    c.ap_name, c.a_p, k, v.eps_rho, v.eps_gradp, v.lateral, v.neighbours);
}

// The report links the method document beside it.
void write_method_document(OutputFolder& output)
{
    if (std::ifstream method{data_folder("docs") / "method.md"}) {
        std::ostringstream text;
        text << method.rdbuf();
        output.write("method.md", text.str());
    } else {
        spdlog::warn("{}: not found; the report's link to method.md will not resolve",
                     (data_folder("docs") / "method.md").string());
    }
}

} // namespace

void write_results_folder(OutputFolder& output, const Study& study, const StudyResults& results,
                          const std::vector<std::string>& figures)
{
    output.write("results.json", [&](std::ostream& out) { write_study_results_json(out, study, results); });
    output.write("curves.csv", [&](std::ostream& out) { write_curves_csv(out, results); });
    output.write("report.md", report_markdown(study, results, figures));
    write_method_document(output);
}

} // namespace sphkern
