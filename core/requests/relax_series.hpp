// `relax --history NAME.pvd`: the run as a ParaView series. Each step's particles go to their
// own NAME_k.vtu beside NAME.pvd as the step ends (not held in memory), the collection NAME.pvd
// last, so that a .pvd on disk always lists complete files.
#pragma once

#include "relax/relaxation.hpp"
#include "support/io/vtk_xml.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sphkern {

// True for a name ending in .pvd (in any case): a series rather than the history's CSV.
bool is_pvd_name(const std::string& path);

class RelaxSeries {
public:
    // `steps`: the most steps the run may take (the names are padded to its digits).
    RelaxSeries(std::filesystem::path pvd, int steps);
    // A run that ends before finish() (an error, an interruption) takes its .vtu files with it.
    ~RelaxSeries();
    RelaxSeries(const RelaxSeries&) = delete;
    RelaxSeries& operator=(const RelaxSeries&) = delete;

    // Every .vtu the run may write, step 0 to `steps`, for the output checks before the run.
    std::vector<std::string> member_files() const;
    // The particles after `step`: positions, and as point data id, e0, e1 (h sum_j V grad W_ij),
    // displacement (since the start, not wrapped) and, with the pressure method, velocity.
    // Its timestep is the step's time (d / c) with the pressure method, the step's number with
    // shift (whose steps have no time).
    void write_step(const RelaxState& state, const RelaxStep& step);
    // The collection of the steps written, written last.
    void finish();

private:
    std::filesystem::path pvd_;
    std::size_t last_;
    std::vector<PvdEntry> entries_;
    std::vector<std::filesystem::path> written_;
    bool finished_ = false;
};

} // namespace sphkern
