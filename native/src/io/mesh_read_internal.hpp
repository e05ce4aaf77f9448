// Private helpers of the mesh readers (native/src/io): splitting text into numbered lines and
// fields, strict number parsing, and the one-line error messages.
// (mesh_io.cpp has similar helpers for the point readers in an anonymous namespace; these are
// the few the mesh readers need.)
#pragma once

#include "hullkit/mesh_io.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
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

/// `field` in double quotes, shortened to 40 characters, every byte that is not printable ASCII
/// shown as '?', for messages.
std::string quote(std::string_view field);

/// Lower-cased extension of `source` without the dot ("" if none).
std::string extension_of(const std::string& source);

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

/// Appends the triangles of a fan over `corners` (v0 v1 v2, v0 v2 v3, ...).
void append_fan(const std::vector<std::uint32_t>& corners, std::vector<std::uint32_t>* triangles);

}  // namespace hullkit::io
