// gnuplot, found on PATH and run on a script without a shell.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// The gnuplot executable on PATH (absolute folders only), or empty.
std::filesystem::path find_gnuplot();

// The figure formats: svg, png and pdf (gnuplot's svg, pngcairo and pdfcairo terminals).
// "svg,png" -> {"svg", "png"}; Error(usage) naming `option` for anything else.
std::vector<std::string> parse_figure_formats(const std::string& list, const std::string& option);

// Writes `body` (a script without terminal or output) to folder/name.gp and runs gnuplot
// on it inside `folder` once per format (an argument vector, a time bound), with the
// terminal at width x height pixels (pdf: 96 per inch) and the output name.<format>.
// Error(output) if gnuplot fails, times out or is killed.
void render_figure(const std::filesystem::path& folder, const std::string& name, int width, int height,
                   const std::string& body, const std::vector<std::string>& formats,
                   const std::filesystem::path& gnuplot);

} // namespace sphkern
