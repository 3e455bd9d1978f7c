#include "study/canvas.hpp"

#include "study/gnuplot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sphkern {

void Canvas::draw(const std::string& name, int width, int height, const std::string& body)
{
    render_figure(folder, name, width, height, body, formats, gnuplot);
    std::string shown = formats.front();
    for (const char* f : {"pdf", "png", "svg"})
        if (std::find(formats.begin(), formats.end(), f) != formats.end()) shown = f;
    written.push_back(folder.filename().string() + "/" + name + "." + shown);
}

void SymLog::add(double y)
{
    if (!std::isfinite(y)) return;
    if (y < 0) below = std::max(below, -y);
    else above = std::max(above, y);
}

std::string SymLog::using_column(int column) const { return fmt::format("(asinh(${}/{:g}))", column, scale); }

std::string SymLog::decades(double largest, int sign) const
{
    const int first = static_cast<int>(std::ceil(std::log10(scale) - 1e-9));
    const int last = std::max(first, static_cast<int>(std::ceil(std::log10(std::max(largest, scale)) - 1e-9)));
    const int stride = last - first >= 7 ? 2 : 1;
    std::string s;
    // The decade at the scale itself sits next to 0; left out when others follow.
    for (int j = last - first >= 2 ? first + 1 : first; j <= last; j += stride) {
        const double v = std::pow(10.0, j);
        s += fmt::format(", '{}{:g}' {:.6f}", sign < 0 ? "-" : "", v, sign * std::asinh(v / scale));
    }
    return s;
}

std::string SymLog::tics() const
{
    const double bottom = std::asinh(std::max(below, scale) / scale) * 1.05,
                 top = std::asinh(std::max(above, scale) / scale) * 1.05;
    return "set ytics ('0' 0" + decades(below, -1) + decades(above, 1) +
           fmt::format(")\nset yrange [{:.6f}:{:.6f}]\n", -bottom, top);
}

std::pair<int, int> layout(std::size_t n)
{
    const int columns = std::min<int>(3, static_cast<int>(n));
    return {(static_cast<int>(n) + columns - 1) / columns, columns};
}

} // namespace sphkern
