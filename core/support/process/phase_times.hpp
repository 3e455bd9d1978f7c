// Wall seconds of each phase of a run (read, h, volumes, grid, sums, statistics, write), so
// that a user and a benchmark see where the time goes. A phase that runs more than once (a
// sweep) adds up.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace sphkern {

class PhaseTimes {
public:
    using Clock = std::chrono::steady_clock;

    void add(const std::string& phase, double seconds)
    {
        for (auto& [name, total] : phases_)
            if (name == phase) {
                total += seconds;
                return;
            }
        phases_.emplace_back(phase, seconds);
    }
    // Adds the time since the last lap (or since construction) to `phase`.
    void lap(const std::string& phase)
    {
        const auto now = Clock::now();
        add(phase, std::chrono::duration<double>(now - last_).count());
        last_ = now;
    }
    void restart() { last_ = Clock::now(); }
    void merge(const PhaseTimes& other)
    {
        for (const auto& [name, seconds] : other.phases_) add(name, seconds);
    }
    const std::vector<std::pair<std::string, double>>& phases() const { return phases_; }

private:
    std::vector<std::pair<std::string, double>> phases_; // in the order they first ran
    Clock::time_point last_ = Clock::now();
};

} // namespace sphkern
