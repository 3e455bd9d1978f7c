// The table of a study's optional sections, in the order they are read, run, written to
// results.json, reported and plotted. Adding a section is its folder and a row here.
#pragma once

#include "study/sections/study_section.hpp"

#include <filesystem>
#include <memory>
#include <vector>

namespace sphkern {

struct SectionKind {
    const char* key; // in the study file and in results.json
    std::shared_ptr<const StudySection> (*read)(const JsonNode& node, const std::filesystem::path& study_file);
};

const std::vector<SectionKind>& section_table();

} // namespace sphkern
