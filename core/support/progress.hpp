// Progress of long work on stderr, shown only when stderr is a terminal.
#pragma once

#include <cstddef>
#include <string>

namespace sphkern {

class Progress {
public:
    Progress(std::string what, std::size_t total);
    ~Progress();
    void step(const std::string& item);

private:
    std::string what_;
    std::size_t total_, done_ = 0;
    bool enabled_;
};

} // namespace sphkern
