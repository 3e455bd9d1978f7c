#include "requests/relax_series.hpp"

#include "support/io/atomic_file.hpp"

#include <algorithm>
#include <cctype>
#include <span>

namespace sphkern {

bool is_pvd_name(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".pvd";
}

RelaxSeries::RelaxSeries(std::filesystem::path pvd, int steps)
    : pvd_(std::move(pvd)), last_(static_cast<std::size_t>(steps))
{}

RelaxSeries::~RelaxSeries()
{
    if (finished_) return;
    std::error_code ignored;
    for (const auto& file : written_) std::filesystem::remove(file, ignored);
}

std::vector<std::string> RelaxSeries::member_files() const
{
    std::vector<std::string> files;
    for (std::size_t k = 0; k <= last_; ++k) files.push_back(pvd_member_path(pvd_, k, last_).string());
    return files;
}

void RelaxSeries::write_step(const RelaxState& s, const RelaxStep& step)
{
    const std::size_t n = s.set.size();
    const bool three = s.set.dimension == 3;
    const auto& f = s.forces;
    const auto& model = s.model;
    // z and the vectors' third components are 0 in 2D.
    auto span = [n](const auto& v) { return std::span<const double>(v.data(), n); };
    auto vector = [three](const char* name, const std::vector<double>& x, const std::vector<double>& y,
                          const std::vector<double>& z, double scale) {
        return VtuArray{name, 3, [&x, &y, &z, three, scale](std::size_t i, int c) {
                            return c == 0 ? x[i] * scale : c == 1 ? y[i] * scale : three ? z[i] * scale : 0.0;
                        }};
    };
    std::vector<VtuArray> arrays{
        {"id", 1, [](std::size_t i, int) { return static_cast<double>(i); }},
        // As the history's rms_e0 and rms_e1 (relax/relaxation.cpp, record_errors).
        {"e0", 1, [&](std::size_t i, int) { return f.density[i] / model.mass * model.volume - 1; }},
        vector("e1", f.gx, f.gy, f.gz, model.h),
        vector("displacement", s.ux, s.uy, s.uz, 1.0),
    };
    if (model.pressure) arrays.push_back(vector("velocity", s.vx, s.vy, s.vz, 1.0));
    const auto file = pvd_member_path(pvd_, static_cast<std::size_t>(step.step), last_);
    write_file_atomically(file, [&](std::ostream& out) {
        write_vtu(out, {span(s.set.x), span(s.set.y), three ? span(s.set.z) : std::span<const double>{}}, arrays);
    });
    written_.push_back(file);
    entries_.push_back({model.pressure ? step.time : static_cast<double>(step.step), file.filename().string()});
}

void RelaxSeries::finish()
{
    write_file_atomically(pvd_, [&](std::ostream& out) { write_pvd(out, entries_); });
    finished_ = true;
}

} // namespace sphkern
