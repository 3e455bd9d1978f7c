// Where a study's figures are drawn (gnuplot, in the formats asked for), and what every
// figure shares: the colours, the legend's place, the panel size, the multiplot layout and
// a symmetric logarithmic axis.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sphkern {

inline constexpr const char* curve_colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
// Branches in colours apart from the blue and red of the stable and unstable marks.
inline constexpr const char* branch_colours[] = {"#000000", "#ff7f0e", "#9467bd", "#8c564b", "#17becf", "#7f7f7f"};
inline constexpr const char* key_setup =
    "set key outside right top vertical Left reverse samplen 1.5 width -2 font ',8' noenhanced\n";
inline constexpr int panel_width = 520, panel_height = 380;

// `written` collects one file per figure for the report (the first of svg, png, pdf asked for).
struct Canvas {
    std::filesystem::path folder;
    std::vector<std::string> formats;
    std::filesystem::path gnuplot;
    std::vector<std::string> written;

    // `body`: a gnuplot script without terminal and output, drawn at width x height pixels.
    void draw(const std::string& name, int width, int height, const std::string& body);
};

// A symmetric logarithmic axis: y is drawn at asinh(y / scale), linear within +-scale and
// logarithmic beyond, so that values near zero (which decide a verdict) and values far
// from it fit in one panel. The range reaches the data on each side (at least +-scale),
// with ticks at 0 and at each decade (every other one when there are many).
struct SymLog {
    double scale;
    double below = 0, above = 0; // the largest |y| of the negative and of the positive values

    void add(double y);
    std::string using_column(int column) const;
    std::string tics() const;

private:
    std::string decades(double largest, int sign) const;
};

// "rows,columns" of a multiplot of n panels, at most three across.
std::pair<int, int> layout(std::size_t n);

} // namespace sphkern
