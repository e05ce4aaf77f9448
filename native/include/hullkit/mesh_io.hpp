// hullkit: reading point sets and writing hulls as text. No geometry lives here.
//
// Readers take the whole text in memory plus a `source` name (a file name or "<stdin>") that
// every error message starts with. Errors are a single line "source:LINE: what is wrong"
// (LINE 1-based), or "source: what is wrong" when no single line is to blame (empty input).
#pragma once

#include "hullkit/hull.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace hullkit {

/// Points read from text, flat x0 y0 z0 x1 y1 z1 ... (size always a multiple of 3).
struct PointsResult {
    std::vector<double> xyz;
    std::string error;  ///< empty on success; on failure `xyz` is empty
    /// What the reader skipped but read on past, one line per kind with its count and first line,
    /// without the source name: `skipped 1 unknown OBJ record "648" (first at line 1)`.
    std::vector<std::string> warnings;

    bool ok() const { return error.empty(); }
    std::size_t count() const { return xyz.size() / 3; }
};

/// Parses points, detecting the format from the first line that is not blank or a '#' comment:
///   - "OFF" ........................ OFF: "nv nf ne", then nv lines "x y z"; faces are ignored.
///   - an OBJ keyword (v, vn, f, o, ...) OBJ: each "v x y z [w]" is a point (also the common
///     or a source named .obj           "v x y z r g b" colour extension); other OBJ records are
///                                    ignored, and unknown records (FCL's "648 1292" count line)
///                                    skipped with a warning (PointsResult::warnings).
///   - one integer, optionally followed by a non-numeric comment ("3 rbox 1000 s D3"):
///                                    qhull/rbox: dimension (must be 3), point count, points.
///   - anything else .................. plain "x y z" lines, separated by whitespace or one comma;
///                                    a first line of three column names ("x,y,z", as CSV files
///                                    start) is skipped, with the warning
///                                    `skipped header line 1: x,y,z`.
/// In every format blank lines are skipped and '#' starts a comment that runs to the end of
/// the line; a UTF-8 byte-order mark at the start is skipped. Coordinates are parsed like strtod
/// but the whole token must be a number, and a finite one: "nan", "inf" or a number beyond the
/// double range is an error naming the line and the point (counted from 0 in this input):
/// `points.txt:5: coordinate "1e400" of point 3 is out of the double range`,
/// `coordinate "nan" of point 3 is not a finite number`.
/// An input without a single point (empty, only comments, a count of 0) gives no points and no
/// error: the hull of nothing has dimension -1.
/// Input that is not text (binary data, binary STL) or a format not read here (PLY, ASCII STL)
/// is rejected as such ("source: not a point file: binary STL is not supported ..."), never
/// with a complaint about coordinates, and no byte of it is echoed.
/// The text is parsed in pieces on `threads` threads (0: every hardware thread, 1: the calling
/// thread only; hullkit::PointReader); the points and messages never depend on the count.
PointsResult parse_points(const std::string& text, const std::string& source, unsigned threads = 0);

/// parse_points on an open file (or stdin), read from its current position in batches through
/// hullkit::PointReader (text-only), so the whole text is never in memory; each batch is parsed
/// on `threads` threads. For a regular file its size sizes the point array once. `source` starts
/// the error messages; a read error gives "source: cannot read: REASON".
PointsResult read_points_file(std::FILE* file, const std::string& source, unsigned threads = 0);
/// The same for a path: "PATH: cannot open: REASON" if it cannot be opened.
PointsResult read_points_file(const std::string& path, unsigned threads = 0);

/// 2D points read from text, flat x0 y0 x1 y1 ... (size always even).
struct Points2Result {
    std::vector<double> xy;
    std::string error;  ///< empty on success; on failure `xy` is empty
    std::vector<std::string> warnings;  ///< as PointsResult::warnings

    bool ok() const { return error.empty(); }
    std::size_t count() const { return xy.size() / 2; }
};

/// Parses 2D points (native/src/io/points2d.cpp), detecting the format from the first content line:
///   - one integer, optionally followed by a non-numeric comment ("2 rbox 1000 D2"): qhull/rbox:
///     dimension (2, or 3 whose z is ignored), point count, points;
///   - anything else: "x y" lines, or "x y z" lines whose z is ignored (every line as the first),
///     separated by whitespace or one comma; a first line of two or three column names ("x,y") is
///     skipped with a warning, as parse_points does.
/// Blank lines, '#' comments, a byte-order mark and an input without points as parse_points; a
/// coordinate that is not a finite number is an error naming its line and point (`coordinate
/// "nan" of point 2 is not a finite number`, `coordinate "1e400" of point 2 is out of the double
/// range`). With `point_lines`, also the 1-based line number of each
/// point (for later messages about a point). Binary data, PLY, STL (ASCII or binary), OFF and OBJ
/// are refused with "not a point file: ..." saying which (read meshes with read_mesh and take
/// their vertices instead).
Points2Result parse_points_2d(const std::string& text, const std::string& source,
                              std::vector<std::size_t>* point_lines = nullptr);

/// A triangle mesh read from an OFF file: points plus 3 indices per triangle.
struct MeshResult {
    std::vector<double> xyz;
    std::vector<std::uint32_t> triangles;
    std::string error;  ///< empty on success; on failure the other fields are empty
    std::vector<std::string> warnings;  ///< as PointsResult::warnings

    bool ok() const { return error.empty(); }
    std::size_t point_count() const { return xyz.size() / 3; }
    std::size_t triangle_count() const { return triangles.size() / 3; }
};

/// Reads an OFF mesh (as written by write_off). Faces with more than 3 vertices are
/// fan-triangulated (v0 v1 v2, v0 v2 v3, ...); trailing per-face colour values are ignored.
/// Errors: not OFF, bad counts, bad numbers, a face index out of range, fewer faces or
/// vertices than the header declares, or content after the last face.
MeshResult read_off_mesh(const std::string& text, const std::string& source);

/// Reads a whole file (binary-safe). Returns false and sets *error to
/// "PATH: cannot open: REASON" / "PATH: cannot read: REASON" on failure.
bool read_file(const std::string& path, std::string* out, std::string* error);

// ---- writers ----
// All writers emit only the hull's vertices, in the order of Hull::vertices, with coordinates
// in the shortest form that reads back to the same doubles (std::to_chars). A hull of lower
// dimension (a polygon, segment or point) is written the same way: its triangles, if any, and
// its vertices. They throw std::invalid_argument if `hull` does not fit `points` (an index out
// of range, a vertex listed twice, or a triangle corner not listed in Hull::vertices); a Hull
// returned by hullkit::hull for `points` always fits.

enum class OutputFormat { Off, Obj, Json, Xyz, Glb, Normals };

/// "off", "obj", "json", "xyz", "glb", "normals".
const char* output_format_name(OutputFormat format);
/// Parses "off" / "obj" / "json" / "xyz" / "glb" / "normals" (lower case); returns false and leaves
/// *out alone otherwise.
bool parse_output_format(const std::string& name, OutputFormat* out);
/// Picks the format from a file name's extension (".off", ".obj", ".json", ".xyz", ".glb",
/// ".normals", any case); returns false and leaves *out alone for any other name.
bool output_format_from_path(const std::string& path, OutputFormat* out);

/// "OFF", "H F 0", H lines "x y z", F lines "3 i j k" with i j k indexing the listed vertices.
std::string write_off(PointSpan points, const Hull& hull);
/// H lines "v x y z", then F lines "f i j k" (1-based into the listed vertices).
std::string write_obj(PointSpan points, const Hull& hull);
/// One line, self-contained: {"vertices":[input indices],"triangles":[[i,j,k],...],
/// "points":[[x,y,z],...],"equations":[[nx,ny,nz,offset],...],"volume":V,"area":A,"dimension":D}.
/// "points" holds the hull's vertices (in the order of Hull::vertices), "triangles" index "points"
/// (as OFF's faces index its vertex lines), "vertices"[k] is the input index of "points"[k] (so
/// the triangle [i,j,k] is the input's points vertices[i], vertices[j], vertices[k]), "equations"
/// has the plane of each triangle (plane_equations: outward unit normal and offset,
/// n . x + offset <= 0 inside); with merged faces also "faces", polygons indexing "points".
/// `index`, when given, maps the hull's indices into `points` to the input's indices (a hull of
/// a subset of the input, as HullBuilder returns: StreamedHull::index); JSON and XYZ write those.
std::string write_json(PointSpan points, const Hull& hull, const std::uint64_t* index = nullptr);
/// The hull's vertices alone, in the order of Hull::vertices, after a '#' comment line: one
/// "x y z # INDEX" line each (INDEX: the input index), which parse_points reads back as points.
std::string write_xyz(PointSpan points, const Hull& hull, const std::uint64_t* index = nullptr);
/// Binary glTF 2.0 (.glb), bytes not text: one mesh with one primitive, the hull's vertices (in the
/// order of Hull::vertices) as float32 POSITION, rounded to the nearest float (so not exact, unlike
/// the text formats), and its triangles as uint32 indices into them; a hull without triangles (a
/// segment, a point) is a POINTS primitive, an empty one a scene without nodes. Throws
/// std::domain_error for a coordinate beyond float's range (about 3.4e38).
std::string write_glb(PointSpan points, const Hull& hull);
/// The plane of each face as qconvex's `n` writes them: a line "4" (the dimension plus one), a
/// line with the face count F, then F lines "nx ny nz offset" (plane_equations; with merged faces,
/// one per polygon, from its first three corners; else one per triangle).
std::string write_normals(PointSpan points, const Hull& hull);
/// Dispatches to one of the writers above.
std::string write_hull(OutputFormat format, PointSpan points, const Hull& hull, const std::uint64_t* index = nullptr);
/// write_hull straight into `file` in ~1 MiB pieces (the text is never held whole). Returns
/// false with *error_number = errno if a write failed; throws like the writers above.
bool write_hull_file(OutputFormat format, PointSpan points, const Hull& hull, std::FILE* file, int* error_number,
                     const std::uint64_t* index = nullptr);

/// A double as the shortest text that reads back to the same value ("0.1", "1", "1e+22");
/// JSON has no NaN/inf, so
/// non-finite values come out as "null" from format_json_number.
std::string format_double(double value);
std::string format_json_number(double value);

/// For each of the `wanted` points, the lowest index of an input point with exactly the same
/// coordinates (-0 and +0 alike), or -1 when there is none. Used to tie the vertices of a hull file
/// back to the input points.
std::vector<std::int64_t> match_points(PointSpan points, PointSpan wanted);

}  // namespace hullkit
