// CSV with a header line: columns named x, y[, z][, h][, m][, rho] (or the names of
// column_names.cpp), separated by ',' or ';'; lines before the header (comments, blank lines,
// the head lines DualSPHysics writes) and blank lines are skipped; other columns are ignored.
#include "particles/formats/column_names.hpp"
#include "particles/formats/particle_files.hpp"

#include "particles/particles_memory.hpp"
#include "support/error.hpp"
#include "support/io/json_input.hpp"

#include <fmt/format.h>

#include <charconv>
#include <optional>
#include <string_view>

namespace sphkern {

namespace {

std::vector<std::string_view> split(std::string_view line, char separator)
{
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = line.find(separator, start);
        fields.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    if (fields.size() > 1 && fields.back().find_first_not_of(" \t\r") == std::string_view::npos) fields.pop_back();
    return fields;
}

double parse_number(std::string_view text, const std::string& where)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size())
        fail_input(fmt::format("{}: \"{}\" is not a number", where, text));
    return value;
}

// A line's separator: ';' where it has one (DualSPHysics' default), else ','.
char separator_of(std::string_view line) { return line.find(';') != std::string_view::npos ? ';' : ','; }

bool names_x_and_y(std::string_view line)
{
    bool x = false, y = false;
    for (const auto name : split(line, separator_of(line))) {
        const auto field = particle_field(name);
        x = x || field == ParticleField::x, y = y || field == ParticleField::y;
    }
    return x && y;
}

// The header: the first line naming columns x and y. The lines before it are skipped: blank
// lines, comments ('#') and the free-text head lines DualSPHysics' CSV writer (JOutputCsv) may
// put before its header (a few: the search stops after 64 lines that are no comment). Without
// such a line, the first line that is no comment (refused by the caller for the column it
// lacks). `rest` and `line_number` are left after the header; "" where there is no line.
std::string_view csv_header(std::string_view& rest, std::size_t& line_number)
{
    struct Line {
        std::string_view text, after;
        std::size_t number = 0;
    };
    std::optional<Line> first;
    std::size_t looked = 0;
    for (std::size_t number = 1; !rest.empty() && looked < 64; ++number) {
        const std::size_t end = rest.find('\n');
        std::string_view line = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.find_first_not_of(" \t") == std::string_view::npos || line.front() == '#') continue;
        if (!first) first = Line{line, rest, number};
        ++looked;
        if (names_x_and_y(line)) {
            line_number = number;
            return line;
        }
    }
    if (!first) return {};
    rest = first->after, line_number = first->number;
    return first->text;
}

} // namespace

ParticleSet read_csv_particles(const std::filesystem::path& file, const ParticleFileOptions&)
{
    const std::string name = file.string();
    const std::string text = read_input_file(file, particle_file_byte_limit(), "a CSV particle file");
    std::string_view rest(text);
    std::size_t line_number = 0;
    auto next_line = [&](std::string_view& line) {
        if (rest.empty()) return false;
        const std::size_t end = rest.find('\n');
        line = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        ++line_number;
        return true;
    };
    const std::string_view header = csv_header(rest, line_number);
    if (header.empty()) fail_input(name + ": no header line; expected column names x, y[, z][, h][, m][, rho]");
    const char separator = separator_of(header);
    const auto names = split(header, separator);
    std::vector<int> column_of(6, -1);
    for (std::size_t c = 0; c < names.size(); ++c)
        if (auto field = particle_field(names[c])) {
            int& slot = column_of[static_cast<std::size_t>(*field)];
            if (slot >= 0)
                fail_input(fmt::format("{}: line {}: columns {} and {} both give {}", name, line_number, slot + 1,
                                       c + 1, field_name(*field)));
            slot = static_cast<int>(c);
        }
    if (column_of[0] < 0 || column_of[1] < 0)
        fail_input(fmt::format("{}: line {}: no column {}; expected a header with x, y[, z][, h][, m][, rho]", name,
                               line_number, column_of[0] < 0 ? "x" : "y"));
    ParticleSet set;
    set.name = name;
    set.dimension = column_of[2] >= 0 ? 3 : 2;
    if (set.dimension == 2) set.gravity = Eigen::Vector3d(0, -1, 0);
    ParticleValues* targets[6] = {&set.x, &set.y, &set.z, &set.h, &set.mass, &set.density};
    std::string_view line;
    while (next_line(line)) {
        if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
        const auto fields = split(line, separator);
        if (fields.size() != names.size())
            fail_input(fmt::format("{}: line {} (particle {}): {} fields, expected {} as in the header", name,
                                   line_number, set.x.size(), fields.size(), names.size()));
        const std::size_t id = set.x.size();
        for (std::size_t f = 0; f < 6; ++f)
            if (column_of[f] >= 0)
                targets[f]->push_back(
                    parse_number(fields[static_cast<std::size_t>(column_of[f])],
                                 fmt::format("{}: line {}, column {} (particle {})", name, line_number,
                                             field_name(static_cast<ParticleField>(f)), id)));
    }
    if (set.dimension == 2) set.z.assign(set.x.size(), 0.0);
    return set;
}

} // namespace sphkern
