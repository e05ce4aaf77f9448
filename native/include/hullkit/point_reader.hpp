// hullkit: reading point files larger than memory in one streaming pass, parsing text on every
// core.
//
// PointReader hands out the points of a file batch by batch, in input order. Text (xyz, rbox,
// OBJ, OFF) is read about batch_bytes at a time and each batch is parsed in pieces on threads;
// PLY point clouds and meshes (ascii or binary) stream their vertex element; STL is read whole
// and handed out at once. Whatever the batch size and thread count, the points and the error
// message are exactly those of hullkit::read_points on the file's bytes (or, with text_only,
// hullkit::parse_points on its text).
//
//     hullkit::PointReader reader(stdin, "<stdin>");
//     std::vector<double> xyz;
//     while (reader.next(&xyz)) builder.add(xyz, first_index), first_index += xyz.size() / 3;
//     if (!reader.error().empty()) fail(reader.error());
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hullkit {

struct PointReaderOptions {
    /// Threads that parse a batch of text: 0, every hardware thread; 1, the calling thread only.
    /// The WebAssembly build always uses the calling thread. The results never depend on it.
    unsigned threads = 0;
    /// Text read and parsed per batch (a PLY: about this many bytes of records). The reader holds
    /// about one batch of text plus its points (24 bytes a point) at a time. A batch that stays
    /// in the caches is read faster: 6.25e6 points of binary PLY took 0.6-0.9 s in batches of
    /// 32 MB and 0.16-0.3 s in batches of 4 MB.
    std::size_t batch_bytes = std::size_t{4} << 20;
    /// true: only the text formats of parse_points (xyz, rbox, OBJ, OFF), with its messages for
    /// PLY, STL and binary data; false: every format hullkit::read_points reads.
    bool text_only = false;
};

class PointReader {
public:
    /// Reads `file` from its current position; it is not closed. `source` (a file name, or
    /// "<stdin>") starts every error message and, as for read_points, its extension (.ply,
    /// .stl, .obj, .off) picks the format before the content does. The format and any header
    /// are read here: declared_points() is known once the reader is constructed.
    PointReader(std::FILE* file, std::string source, PointReaderOptions options = {});
    /// Reads text held in memory, which must outlive the reader.
    PointReader(std::string_view text, std::string source, PointReaderOptions options = {});
    ~PointReader();
    PointReader(PointReader&&) noexcept;
    PointReader& operator=(PointReader&&) noexcept;

    /// The next batch of points (x y z flat, replacing *xyz's contents, at least one point), in
    /// input order. False at the end of the input, or on an error: then error() is non-empty,
    /// *xyz is empty, and the batches already handed out stand (a streaming consumer has seen
    /// points before the bad line; read_points would have returned none).
    bool next(std::vector<double>* xyz);
    /// next(), but appending the batch to *xyz (for a caller that keeps every point).
    bool append_next(std::vector<double>* xyz);

    /// "source:LINE: what is wrong" or "source: what is wrong"; empty while all is well.
    const std::string& error() const;
    /// What was skipped so far, as PointsResult::warnings (complete once next() returned false
    /// without an error): `skipped 1 unknown OBJ record "648" (first at line 1)`.
    std::vector<std::string> warnings() const;
    /// Points handed out so far.
    std::uint64_t points_read() const;
    /// Bytes of the input consumed so far (for a progress bar against size()).
    std::uint64_t bytes_read() const;
    /// The input's size in bytes from where reading started, when known (a regular file, or
    /// text in memory), else 0.
    std::uint64_t size() const;
    /// The number of points a header declared (rbox, OFF, PLY), else 0.
    std::uint64_t declared_points() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace hullkit
