// Large text outputs: formatted into a buffer with fmt and handed to the stream in
// chunks of about a megabyte, instead of a string per line or one string for all.
#pragma once

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
