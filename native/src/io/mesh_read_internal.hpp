// Private helpers of the readers (native/src/io): splitting text into numbered lines and
// fields, strict number parsing, the one-line error messages, and the pieces that PointReader
// (point_reader.cpp) streams through: an input read in chunks, the point-text header and body
// parser of point_text.cpp, and the PLY body reader of ply.cpp.
// (text_fields.hpp has similar line and number helpers for the point readers, in io::text;
// these are the few the mesh readers need.)
#pragma once

#include "hullkit/mesh_io.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hullkit::io {

/// Walks a text line by line ("\n", "\r\n" or "\r" line ends), counting lines from 1.
class LineCursor {
public:
    explicit LineCursor(std::string_view text, std::size_t start = 0) : text_(text), pos_(start) {}

    /// The next line without its line end; false at the end of the text.
    bool next(std::string_view* line) {
        if (pos_ >= text_.size()) return false;
        std::size_t end = pos_;
        while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
        *line = text_.substr(pos_, end - pos_);
        if (end < text_.size() && text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n') ++end;
        pos_ = end + 1;
        ++number_;
        return true;
    }
    std::size_t line_number() const { return number_; }
    /// Byte offset just after the last line returned (its line end included).
    std::size_t offset() const { return pos_ < text_.size() ? pos_ : text_.size(); }

private:
    std::string_view text_;
    std::size_t pos_;
    std::size_t number_ = 0;
};

/// The whitespace-separated fields of `line`, cut at `comment` (0: no comment character).
std::vector<std::string_view> split_words(std::string_view line, char comment);

/// The whole field as a finite double (strtod syntax, no trailing characters).
bool parse_finite(std::string_view field, double* out);
/// The whole field as a decimal integer (optional sign); false if it does not fit int64.
bool parse_integer(std::string_view field, std::int64_t* out);

/// `text` shortened to 40 characters (then "..."), every byte that is not printable ASCII shown as
/// '?', for messages: no byte of a file (control codes, invalid UTF-8) reaches a terminal.
std::string printable(std::string_view text);
/// `field` as printable() gives it, in double quotes.
std::string quote(std::string_view field);
/// What is wrong with a coordinate `field` that parsed to a non-finite double: "is out of the
/// double range" for digits too large for a double ("1e400"), else "is not a finite number"
/// ("nan", "-inf").
const char* non_finite_reason(std::string_view field);
/// 3 if `text` starts with the UTF-8 byte-order mark (EF BB BF) that some editors write at the
/// start of a text file, else 0. The point readers skip it.
std::size_t bom_length(std::string_view text);

/// Lower-cased extension of `source` without the dot ("" if none).
std::string extension_of(const std::string& source);

/// "Not about one point", for describe_problem.
inline constexpr std::size_t kNoPoint = ~std::size_t{0};
/// A reader's message: `what` alone, or for a coordinate of point `point` (not kNoPoint)
/// `what` + " of point N " + `tail`: `coordinate "nan" of point 3 is not a finite number`.
inline std::string describe_problem(const std::string& what, std::size_t point, const std::string& tail) {
    if (point == kNoPoint) return what;
    return what + " of point " + std::to_string(point) + " " + tail;
}

/// A MeshResult holding only `message`.
MeshResult mesh_error(std::string message);
/// "source:LINE: what".
std::string at_line(const std::string& source, std::size_t line, const std::string& what);

/// True if `text` starts with `word` followed by whitespace or the end.
bool starts_with_word(std::string_view text, std::string_view word);
/// A binary STL's size is exactly 84 + 50 * the triangle count stored at byte 80.
bool has_binary_stl_size(const std::string& bytes);
/// The same test for a file of `size` bytes of which `head` holds the first (at least 84 of them).
bool has_binary_stl_size(std::string_view head, std::uint64_t size);
/// ASCII STL starts with "solid"; binary STL headers sometimes do too, so this also wants "facet"
/// or "endsolid" and no NUL byte in the first kilobyte.
bool looks_like_ascii_stl(const std::string& bytes);

/// Records a reader skipped, tallied by kind for the result's `warnings`: one entry per kind,
/// with its count and the first line it was seen on. At most kMaxKinds kinds are named; the
/// rest are counted together as "other".
class SkippedRecords {
public:
    static constexpr std::size_t kMaxKinds = 8;

    /// A record `word` skipped on `line`.
    void add(std::string_view word, std::size_t line);
    /// Appends the tally of a later piece of the same text whose lines are numbered from 1,
    /// `line_base` lines into the text.
    void merge(const SkippedRecords& later, std::size_t line_base);
    bool empty() const { return kinds_.empty(); }
    /// One message per kind: `skipped 2 unknown OBJ records "648" (first at line 1)`, where
    /// `what` is "unknown OBJ record".
    std::vector<std::string> messages(const char* what) const;

private:
    struct Kind {
        std::string word;  ///< empty: the "other" kind
        std::uint64_t count = 0;
        std::size_t first_line = 0;
    };
    void add_kind(const std::string& word, std::uint64_t count, std::size_t first_line);
    std::vector<Kind> kinds_;
};

/// Records that an OBJ file may hold and that carry nothing the readers use (texture and normal
/// vertices, groups, materials, smoothing, polylines, free-form geometry, ...): skipped quietly.
bool is_known_obj_record(std::string_view word);

/// Appends the triangles of a fan over `corners` (v0 v1 v2, v0 v2 v3, ...).
void append_fan(const std::vector<std::uint32_t>& corners, std::vector<std::uint32_t>* triangles);

// ---- streaming input (point_reader.cpp) ----

/// Bytes that are not zero-filled when allocated: a buffer of which only what is read into it is
/// ever written, so a 64 KiB read buffer that gets 100 bytes touches one page, not sixteen.
struct ByteBuffer {
    std::unique_ptr<char[]> data;
    std::size_t size = 0;

    ByteBuffer() = default;
    ByteBuffer(ByteBuffer&& other) noexcept : data(std::move(other.data)), size(std::exchange(other.size, 0)) {}
    ByteBuffer& operator=(ByteBuffer&& other) noexcept {
        data = std::move(other.data);
        size = std::exchange(other.size, 0);
        return *this;
    }
};

/// An input read front to back: all in memory, or a FILE read in chunks into one buffer that
/// holds only what has not been consumed yet (plus whatever a caller asked to see at once).
class ChunkedInput {
public:
    /// All of `text`, which must outlive this.
    explicit ChunkedInput(std::string_view text) : data_(text.data()), end_(text.size()) {}
    /// `file` from its current position, at least `chunk` bytes per read.
    ChunkedInput(std::FILE* file, std::size_t chunk) : file_(file), chunk_(chunk ? chunk : 1), at_end_(false) {}

    /// The bytes read and not consumed yet. Valid until the next fill().
    std::string_view available() const { return std::string_view(data_ + pos_, end_ - pos_); }
    /// Whether the input is read to its end (or to a read error): available() is all that is left.
    bool at_end() const { return at_end_; }
    /// Whether the input is all in memory: then what available() shows stays valid for good.
    bool in_memory() const { return file_ == nullptr; }
    /// Reads until available() holds at least `bytes` or the input ends; whether it holds them.
    bool fill(std::size_t bytes);
    void consume(std::size_t bytes) {
        pos_ += bytes;
        consumed_ += bytes;
    }
    /// Bytes consumed since the start.
    std::uint64_t offset() const { return consumed_; }
    /// errno of a failed read (the input then counts as ended), else 0.
    int read_errno() const { return read_errno_; }
    /// Consumes the first `length` available bytes and returns them, kept valid until *buffer
    /// changes: a file's read buffer is handed over to *buffer (swapped with it) so that the
    /// bytes are not copied; only those after them move, into the buffer *buffer had.
    std::string_view take(std::size_t length, ByteBuffer* buffer);
    /// Reads the rest of the input and consumes it: the bytes from offset() to the end.
    std::string take_rest();

private:
    std::FILE* file_ = nullptr;
    std::size_t chunk_ = 0;
    /// Makes storage_ hold at least `size` bytes, keeping the `keep` bytes at its start.
    void grow(std::size_t size, std::size_t keep);

    ByteBuffer storage_;  ///< the file's unconsumed bytes start at storage_.data[pos_]
    const char* data_ = nullptr;
    std::size_t pos_ = 0;
    std::size_t end_ = 0;
    bool at_end_ = true;
    int read_errno_ = 0;
    std::uint64_t consumed_ = 0;
};

/// How far reading a header got in the input seen so far.
enum class ReadStatus { Done, NeedMore, Failed };

// ---- point text: xyz, rbox, OBJ, OFF, TetGen .node (point_text.cpp) ----

enum class PointTextFormat { Xyz, Rbox, Obj, Off, Node };

/// What comes before the points of point text.
struct PointTextHeader {
    PointTextFormat format = PointTextFormat::Xyz;
    bool counted = false;         ///< rbox, OFF: the header declares the number of points
    std::uint64_t declared = 0;   ///< that number
    std::size_t count_line = 0;   ///< the line that declares it
    std::size_t body_offset = 0;  ///< where the point lines start (xyz, OBJ: the first content line)
    std::size_t body_line = 0;    ///< the number of lines before body_offset
    std::size_t column_names_line = 0;  ///< xyz: the line of a header row of column names ("x,y,z"), 0 if none
    std::string column_names;     ///< that line, printable
    std::size_t node_fields = 4;  ///< .node: fields per point line (index, x, y, z, attributes, marker)
};

/// The warning for a header row of column names that a point reader skipped:
/// `skipped header line 1: x,y,z`.
inline std::string column_names_warning(std::size_t line, const std::string& names) {
    return "skipped header line " + std::to_string(line) + ": " + names;
}

/// Reads the header of point text from `text`, the start of the input made of whole lines;
/// `whole`: the input has nothing more. NeedMore when the header runs past `text`; Failed with
/// *error (the message parse_points gives) when there is no point text or its header is bad.
ReadStatus read_point_text_header(std::string_view text, bool whole, const std::string& source,
                                  PointTextHeader* header, std::string* error);

/// The outcome of parsing a piece of point lines.
struct PointPiece {
    std::size_t points = 0;   ///< points appended (x y z each)
    std::size_t lines = 0;    ///< lines read, the last one included; all of them unless it stopped early
    bool at_limit = false;    ///< OFF: stopped after `limit` points (the rest of the file is faces)
    std::size_t error_line = 0;  ///< 0: no error; else the failing line, counted from the piece's first
    std::string error_what;      ///< what is wrong on that line (see describe_problem)
    std::size_t error_point = kNoPoint;  ///< the point it is about, counted from the piece's first point
    std::string error_tail;      ///< the rest of the message after the point's number
    SkippedRecords skipped;      ///< OBJ: unknown records skipped, lines counted from the piece's first
};

/// Parses `text`, whole lines of the body of point text (of `header`'s format), appending the
/// points to *xyz. After `limit` points, rbox fails at the next content line ("more points than
/// the N declared") and OFF stops (at_limit); xyz and OBJ take no limit. Stops at the first error.
/// Pieces of one body can be parsed in any order, on any thread: each knows only its own lines.
void parse_point_piece(std::string_view text, const PointTextHeader& header, std::uint64_t limit,
                       std::vector<double>* xyz, PointPiece* piece);

/// What is wrong at the end of a counted body (rbox, OFF) that has `found` points, fewer than
/// the header declared ("header declares N points but the file has M"), to report on count_line.
std::string missing_points_message(const PointTextHeader& header, std::uint64_t found);

/// How much of the start of an input parse_points looks at to tell binary data from text.
constexpr std::size_t kSniffBytes = 4096;
/// Empty if `head` (the first bytes of an input of `size` bytes, or of unknown size if not
/// `size_known`) looks like text; else why parse_points cannot read it ("not a point file: ...").
std::string binary_input_message(std::string_view head, std::uint64_t size, bool size_known, const char* expected);

// ---- PLY (ply.cpp) ----

/// A PLY file read from a ChunkedInput element by element, row by row: read_ply_mesh and
/// read_ply_points read all of it in memory, PointReader a stream whose vertices it hands out
/// in batches. Whatever the batches, the points, triangles and messages are the same.
class PlyReader {
public:
    /// Without `faces_required` a file with no "face" element is a point cloud.
    PlyReader(ChunkedInput& input, const std::string& source, bool faces_required);
    ~PlyReader();
    PlyReader(const PlyReader&) = delete;
    PlyReader& operator=(const PlyReader&) = delete;

    /// Reads the header (filling the input as far as it needs) and checks its elements; false
    /// with error() if it is bad.
    bool start();
    /// Reads on through the body, appending the vertices' x y z to *xyz and, if `triangles` is not
    /// null, the faces' triangles (faces are checked either way). Returns once `max_bytes` of the
    /// body were read and a vertex was appended, or at the end (then done()); false on an error.
    bool read(std::uint64_t max_bytes, std::vector<double>* xyz, std::vector<std::uint32_t>* triangles);
    bool done() const;
    /// The vertex count the header declares (after start()).
    std::uint64_t vertex_count() const;
    const std::string& error() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace hullkit::io
