// Inline mesh arrays read ahead of the JSON tree (see scene_arrays.hpp). A scene with a 1e5-
// triangle obstacle inline is 4e5 numbers; as tree nodes (three allocations per [x, y, z], a
// strtod per number) they took two thirds of reading the scene.
#include "scene_arrays.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <utility>

// parse_count, and fast_float when it is there (HULLKIT_HAVE_FAST_FLOAT): correctly rounded, as
// strtod. Without fast_float nothing is taken out of the text and every number goes through the
// JSON parser.
#include "io/text_fields.hpp"

namespace hullkit::route_detail {

#if defined(HULLKIT_HAVE_FAST_FLOAT)
namespace {

// JSON's whitespace, and only it.
const char* skip_space(const char* p, const char* end) {
    while (p < end && (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t')) ++p;
    return p;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The end of the JSON number starting at p (RFC 8259: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?),
/// or nullptr. *integer: written without a fraction or an exponent.
const char* number_end(const char* p, const char* end, bool* integer) {
    if (p < end && *p == '-') ++p;
    if (p == end || !is_digit(*p)) return nullptr;
    if (*p == '0') {
        ++p;
    } else {
        while (p < end && is_digit(*p)) ++p;
    }
    *integer = true;
    if (p < end && *p == '.') {
        ++p;
        if (p == end || !is_digit(*p)) return nullptr;
        while (p < end && is_digit(*p)) ++p;
        *integer = false;
    }
    if (p < end && (*p == 'e' || *p == 'E')) {
        ++p;
        if (p < end && (*p == '+' || *p == '-')) ++p;
        if (p == end || !is_digit(*p)) return nullptr;
        while (p < end && is_digit(*p)) ++p;
        *integer = false;
    }
    return p;
}

/// [p, stop) as a string_view (for io::text::parse_count: digits only, up to a limit).
std::string_view text_of(const char* p, const char* stop) { return {p, static_cast<std::size_t>(stop - p)}; }

/// The number [p, stop) (valid JSON) as the JSON tree's get<double>() gives it: an integer that
/// fits a 64-bit integer is converted from that integer (so "-0" is +0), anything else is the
/// decimal value rounded to nearest.
double number_value(const char* p, const char* stop, bool integer) {
    if (integer) {
        const bool negative = *p == '-';
        std::uint64_t magnitude = 0;
        if (io::text::parse_count(text_of(p + (negative ? 1 : 0), stop), std::numeric_limits<std::uint64_t>::max(), &magnitude)) {
            if (!negative) return static_cast<double>(magnitude);
            if (magnitude <= std::uint64_t{1} << 63) {
                // Two's complement: -2^63 included. Zero stays +0 as an integer does.
                return static_cast<double>(static_cast<std::int64_t>(~magnitude + 1));
            }
        }
    }
    double value = 0.0;
    fast_float::from_chars(p, stop, value);  // the whole token is a number: out-of-range gives +-inf or +-0
    return value;
}

/// [a, b, c] at p (just at '['): three numbers through `take`; the end, or nullptr.
template <class Take>
const char* triple(const char* p, const char* end, Take&& take) {
    if (p == end || *p != '[') return nullptr;
    ++p;
    for (int k = 0; k < 3; ++k) {
        p = skip_space(p, end);
        bool integer = false;
        const char* stop = number_end(p, end, &integer);
        if (!stop || !take(p, stop, integer)) return nullptr;
        p = skip_space(stop, end);
        if (p == end || *p != (k < 2 ? ',' : ']')) return nullptr;
        ++p;
    }
    return p;
}

/// A non-empty array of triples at p (just at '['), each through `take`; the end, or nullptr.
template <class Take>
const char* triples(const char* p, const char* end, Take&& take) {
    ++p;  // '['
    p = skip_space(p, end);
    for (;;) {
        p = triple(p, end, take);
        if (!p) return nullptr;
        p = skip_space(p, end);
        if (p == end) return nullptr;
        if (*p == ']') return p + 1;
        if (*p != ',') return nullptr;
        p = skip_space(p + 1, end);
    }
}

}  // namespace
#endif

bool pack_mesh_arrays(const std::string& text, std::string* packed_text, PackedMeshArrays* arrays) {
    *arrays = PackedMeshArrays{};
    packed_text->clear();
#if !defined(HULLKIT_HAVE_FAST_FLOAT)
    return false;
#else
    const char* p = text.data();
    const char* const end = p + text.size();
    const char* copied = p;  // text before this is in *packed_text
    // Outside strings JSON has no quotes: from quote to quote finds every string, and a string
    // followed by ':' is a key. The arrays between keys are skipped by memchr.
    while (const char* quote = static_cast<const char*>(std::memchr(p, '"', static_cast<std::size_t>(end - p)))) {
        const char* q = quote + 1;
        bool escaped = false;
        while (q < end && *q != '"') {
            if (*q == '\\') {
                escaped = true;
                q += end - q >= 2 ? 2 : 1;
            } else {
                ++q;
            }
        }
        if (q >= end) break;  // an unterminated string: the parser reports it
        p = q + 1;
        const char* colon = skip_space(p, end);
        if (colon == end || *colon != ':') continue;
        if (escaped) return false;  // "\u0076ertices" is "vertices" too
        const std::string_view key(quote + 1, static_cast<std::size_t>(q - quote - 1));
        const bool is_vertices = key == "vertices";
        if (!is_vertices && key != "triangles") continue;
        std::vector<std::int64_t>& keys = is_vertices ? arrays->vertices_keys : arrays->triangles_keys;
        keys.push_back(-1);
        const char* value = skip_space(colon + 1, end);
        if (value == end || *value != '[') continue;
        const char* stop = nullptr;
        std::vector<double> xyz;
        std::vector<std::uint32_t> indices;
        if (is_vertices) {
            stop = triples(value, end, [&xyz](const char* a, const char* b, bool integer) {
                const double x = number_value(a, b, integer);
                xyz.push_back(x);
                return std::isfinite(x);
            });
        } else {
            stop = triples(value, end, [&indices](const char* a, const char* b, bool integer) {
                std::uint64_t i = 0;
                if (!integer || !io::text::parse_count(text_of(a, b), 0xffffffffULL, &i)) return false;  // '-' is no digit
                indices.push_back(static_cast<std::uint32_t>(i));
                return true;
            });
        }
        if (!stop) continue;  // left in the text; the scan goes on inside it, finding no quote
        packed_text->append(copied, value);
        packed_text->append("[]");
        copied = p = stop;
        if (is_vertices) {
            keys.back() = static_cast<std::int64_t>(arrays->vertices.size());
            arrays->vertices.push_back(std::move(xyz));
        } else {
            keys.back() = static_cast<std::int64_t>(arrays->triangles.size());
            arrays->triangles.push_back(std::move(indices));
        }
    }
    if (arrays->vertices.empty() && arrays->triangles.empty()) return false;
    packed_text->append(copied, end);
    return true;
#endif
}

}  // namespace hullkit::route_detail
