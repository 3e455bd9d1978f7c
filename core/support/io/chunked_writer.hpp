// Large text outputs: formatted into a buffer with fmt and handed to the stream in
// chunks of about a megabyte, instead of a string per line or one string for all. Rows of a
// table are formatted by several threads, block by block, and written in their order: the
// text does not depend on the thread count.
#pragma once

#include "support/process/parallel_for.hpp"

#include <fmt/format.h>

#include <iterator>
#include <ostream>
#include <string_view>
#include <utility>

namespace sphkern {

class ChunkedWriter {
public:
    explicit ChunkedWriter(std::ostream& out) : out_(out) {}
    ~ChunkedWriter() { flush(); }
    ChunkedWriter(const ChunkedWriter&) = delete;
    ChunkedWriter& operator=(const ChunkedWriter&) = delete;

    template <class... Args>
    void print(fmt::format_string<Args...> format, Args&&... args)
    {
        fmt::format_to(std::back_inserter(buffer_), format, std::forward<Args>(args)...);
        if (buffer_.size() > (1u << 20)) flush();
    }
    void text(std::string_view s)
    {
        buffer_.append(s.data(), s.data() + s.size());
        if (buffer_.size() > (1u << 20)) flush();
    }
    // format(buffer, row) appends row `row` to `buffer`, for every row in [0, rows).
    template <class Format>
    void rows(std::size_t rows, int threads, const Format& format)
    {
        constexpr std::size_t rows_per_block = 4096;
        flush();
        // A round is a few blocks per thread, so that memory stays bounded on any set.
        const std::size_t per_round = rows_per_block * 4 * static_cast<std::size_t>(std::max(1, threads));
        std::vector<fmt::memory_buffer> blocks((per_round + rows_per_block - 1) / rows_per_block);
        for (std::size_t first = 0; first < rows; first += per_round) {
            const std::size_t count = std::min(per_round, rows - first);
            ParallelFor pass;
            pass.run_blocks(count, rows_per_block, threads, [&](std::size_t b, std::size_t begin, std::size_t end) {
                blocks[b].clear();
                for (std::size_t r = begin; r < end; ++r) format(blocks[b], first + r);
            });
            for (std::size_t b = 0; b * rows_per_block < count; ++b)
                out_.write(blocks[b].data(), static_cast<std::streamsize>(blocks[b].size()));
        }
    }
    void flush()
    {
        out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
        buffer_.clear();
    }

private:
    std::ostream& out_;
    fmt::memory_buffer buffer_;
};

} // namespace sphkern
