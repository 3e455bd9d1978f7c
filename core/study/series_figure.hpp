// A series' figure (requests/particles_series.hpp's script) drawn by gnuplot into a file, for
// the command line's --plot and Python's plot alike.
#pragma once

#include <string>

namespace sphkern {

// svg, png or pdf, from the figure's extension; Error(usage) naming `setting` for another.
std::string series_figure_format(const std::string& figure, const std::string& setting);

// gnuplot draws beside the figure under a hidden name of this process; the figure is then
// renamed into place, complete, and the script removed. Error(output) without gnuplot.
void draw_series_figure(const std::string& figure, const std::string& setting, const std::string& script);

} // namespace sphkern
