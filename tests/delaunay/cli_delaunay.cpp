// Tests of the `hullkit delaunay` and `hullkit verify-delaunay` commands (the built binary,
// HULLKIT_CLI_PATH): every option, every error path, and every output checked independently of
// the library: OFF re-read and checked with GMP rationals (orientation, empty circles, area), JSON
// parsed and compared with the OFF, SVG checked to be well-formed XML.
#include <catch2/catch.hpp>
#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_support.hpp"
#include "delaunay_checks.hpp"
#include "hullkit/mesh_io.hpp"

namespace {

using hullkit_test::RunResult;
using hullkit_test::TempDir;
using hullkit_test::read_text;
using hullkit_test::run_cli;
using hullkit_test::write_text;

using Points = std::vector<double>;  // x0 y0 x1 y1 ...

/// The GMP predicates of the library's own tests (delaunay_checks.hpp), on points given as x y pointers.
int rational_orient2d(const double* a, const double* b, const double* c) {
    return delaunay_test::rational_orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
}
/// > 0 when d is inside the circle through a, b, c given counter-clockwise.
int rational_incircle(const double* a, const double* b, const double* c, const double* d) {
    return delaunay_test::rational_incircle(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]);
}

/// Twice the signed area of a, b, c, exactly.
mpq_class rational_area2(const double* a, const double* b, const double* c) {
    return (mpq_class(b[0]) - a[0]) * (mpq_class(c[1]) - a[1]) - (mpq_class(b[1]) - a[1]) * (mpq_class(c[0]) - a[0]);
}

/// The convex hull's vertices (strictly convex corners only), counter-clockwise, by the exact
/// monotone chain on the distinct points.
std::vector<std::size_t> exact_hull(const Points& xy) {
    std::vector<std::size_t> order(xy.size() / 2);
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
        return std::make_pair(xy[2 * i], xy[2 * i + 1]) < std::make_pair(xy[2 * j], xy[2 * j + 1]);
    });
    std::vector<std::size_t> hull(2 * order.size() + 1);
    std::size_t k = 0;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t start = k;
        for (std::size_t m = 0; m < order.size(); ++m) {
            const std::size_t i = pass == 0 ? order[m] : order[order.size() - 1 - m];
            while (k >= start + 2 && rational_orient2d(&xy[2 * hull[k - 2]], &xy[2 * hull[k - 1]], &xy[2 * i]) <= 0) --k;
            hull[k++] = i;
        }
        --k;  // the last point of a chain starts the next
    }
    hull.resize(k);
    return hull;
}

/// Everything wrong with `triangles` (input indices) as a Delaunay triangulation of the distinct
/// points of `xy`, by brute force with rationals (small inputs only): every triangle clockwise
/// (y up) and not degenerate, each directed edge at most once, the areas adding up to the hull's
/// area (so the triangles tile the hull), every distinct point a corner, and no point strictly
/// inside any triangle's circumcircle.
std::vector<std::string> brute_force_problems(const Points& xy, const std::vector<std::uint32_t>& triangles) {
    std::vector<std::string> problems;
    const std::size_t n = xy.size() / 2;
    auto p = [&](std::size_t i) { return &xy[2 * i]; };
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::set<std::uint32_t> corners;
    mpq_class area = 0;
    for (std::size_t t = 0; 3 * t < triangles.size(); ++t) {
        const std::uint32_t a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
        if (a >= n || b >= n || c >= n) {
            problems.push_back("triangle " + std::to_string(t) + ": index out of range");
            continue;
        }
        if (rational_orient2d(p(a), p(b), p(c)) >= 0) problems.push_back("triangle " + std::to_string(t) + " is not clockwise");
        area -= rational_area2(p(a), p(b), p(c));
        for (auto edge : {std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a)}) {
            if (!edges.insert(edge).second) problems.push_back("edge used twice in one direction");
        }
        corners.insert({a, b, c});
        for (std::size_t d = 0; d < n; ++d) {
            // Clockwise a, b, c: d strictly inside the circle gives a negative determinant.
            if (rational_incircle(p(a), p(b), p(c), p(d)) < 0) {
                problems.push_back("point " + std::to_string(d) + " is inside the circumcircle of triangle " + std::to_string(t));
            }
        }
    }
    const std::vector<std::size_t> hull = exact_hull(xy);
    mpq_class hull_area = 0;
    for (std::size_t k = 1; k + 1 < hull.size(); ++k) hull_area += rational_area2(p(hull[0]), p(hull[k]), p(hull[k + 1]));
    if (area != hull_area) problems.push_back("the triangles' area is not the convex hull's");
    // Every distinct point is a corner (a duplicate's lowest index stands for it).
    std::map<std::pair<double, double>, std::size_t> first;
    for (std::size_t i = 0; i < n; ++i) first.emplace(std::make_pair(xy[2 * i], xy[2 * i + 1]), i);
    for (const auto& entry : first) {
        if (hull.size() >= 3 && !corners.count(static_cast<std::uint32_t>(entry.second))) {
            problems.push_back("point " + std::to_string(entry.second) + " is not a corner");
        }
    }
    return problems;
}

std::string join(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

/// `n` seeded points uniform in [-1, 1]^2 (general position with probability 1).
Points uniform_points(std::size_t n, std::uint32_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Points xy(2 * n);
    for (double& v : xy) v = u(random);
    return xy;
}

/// The integer grid {0..k-1}^2: every unit square's four corners are cocircular.
Points grid_points(int k) {
    Points xy;
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) xy.insert(xy.end(), {double(j), double(i)});
    }
    return xy;
}

std::string xy_lines(const Points& xy) {
    std::string text = "# x y\n";
    for (std::size_t i = 0; i < xy.size(); i += 2) text += hullkit::format_double(xy[i]) + " " + hullkit::format_double(xy[i + 1]) + "\n";
    return text;
}

std::string rbox_text(const Points& xy) {
    std::string text = "2 rbox-style header\n" + std::to_string(xy.size() / 2) + "\n";
    for (std::size_t i = 0; i < xy.size(); i += 2) text += hullkit::format_double(xy[i]) + " " + hullkit::format_double(xy[i + 1]) + "\n";
    return text;
}

/// Reads `hullkit delaunay` OFF output: the points (z must be 0) and the triangles.
void read_delaunay_off(const std::string& text, Points* xy, std::vector<std::uint32_t>* triangles) {
    const hullkit::MeshResult mesh = hullkit::read_off_mesh(text, "output.off");
    REQUIRE(mesh.ok());
    xy->clear();
    for (std::size_t i = 0; i < mesh.point_count(); ++i) {
        REQUIRE(mesh.xyz[3 * i + 2] == 0.0);
        xy->insert(xy->end(), {mesh.xyz[3 * i], mesh.xyz[3 * i + 1]});
    }
    *triangles = mesh.triangles;
}

/// The triangles as a set of rotations starting at the smallest index (comparable across runs).
std::set<std::vector<std::uint32_t>> canonical(const std::vector<std::uint32_t>& triangles) {
    std::set<std::vector<std::uint32_t>> set;
    for (std::size_t t = 0; 3 * t < triangles.size(); ++t) {
        std::vector<std::uint32_t> tri(triangles.begin() + 3 * t, triangles.begin() + 3 * t + 3);
        std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
        set.insert(tri);
    }
    return set;
}

/// One line on stderr starting "hullkit: ", exit status 2, nothing on stdout.
void require_usage_error(const RunResult& run, const std::string& fragment) {
    INFO("stderr: " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    REQUIRE(run.err_lines().size() == 1);
    CHECK(run.err.rfind("hullkit: ", 0) == 0);
    CHECK(run.err.find(fragment) != std::string::npos);
}

/// A small XML well-formedness check: tags nest and close, attributes are quoted, nothing but
/// whitespace outside the root element. Enough to catch a writer bug; not a full XML parser.
std::string xml_problem(const std::string& text) {
    std::vector<std::string> open;
    std::size_t i = 0;
    bool root_seen = false;
    while (i < text.size()) {
        if (text[i] != '<') {
            if (open.empty() && !std::isspace(static_cast<unsigned char>(text[i]))) return "text outside the root element";
            if (text[i] == '&' && text.compare(i, 5, "&amp;") != 0 && text.compare(i, 4, "&lt;") != 0 &&
                text.compare(i, 4, "&gt;") != 0) {
                return "unescaped '&'";
            }
            ++i;
            continue;
        }
        const std::size_t end = text.find('>', i);
        if (end == std::string::npos) return "unterminated tag";
        std::string tag = text.substr(i + 1, end - i - 1);
        i = end + 1;
        if (tag[0] == '?') continue;  // the XML declaration
        if (tag[0] == '/') {
            if (open.empty() || open.back() != tag.substr(1)) return "mismatched </" + tag.substr(1) + ">";
            open.pop_back();
            continue;
        }
        const bool self_closing = tag.back() == '/';
        if (self_closing) tag.pop_back();
        const std::string name = tag.substr(0, tag.find_first_of(" \n\t"));
        // Attributes: name="value" pairs, values without '<' or an unescaped quote.
        std::size_t quotes = std::count(tag.begin(), tag.end(), '"');
        if (quotes % 2 != 0 || tag.find('<') != std::string::npos) return "bad attributes in <" + name + ">";
        if (open.empty()) {
            if (root_seen) return "two root elements";
            root_seen = true;
        }
        if (!self_closing) open.push_back(name);
    }
    if (!open.empty()) return "<" + open.back() + "> is never closed";
    return root_seen ? "" : "no root element";
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t count = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
    return count;
}

}  // namespace

TEST_CASE("delaunay cli: rbox input, OFF output checked by verify-delaunay and by brute force") {
    TempDir dir("hullkit-delaunay-cli");
    const Points xy = uniform_points(60, 11);
    write_text(dir.file("points.txt"), rbox_text(xy));
    const RunResult run = run_cli(dir, {"delaunay", dir.file("points.txt")});
    REQUIRE(run.exit_code == 0);
    CHECK(run.err.empty());

    Points written;
    std::vector<std::uint32_t> triangles;
    read_delaunay_off(run.out, &written, &triangles);
    CHECK(written == xy);  // every input point in input order: OFF indices are input indices
    const std::vector<std::size_t> hull = exact_hull(xy);
    CHECK(triangles.size() / 3 == 2 * 60 - hull.size() - 2);
    CHECK(join(brute_force_problems(xy, triangles)).empty());

    write_text(dir.file("out.off"), run.out);
    const RunResult verified = run_cli(dir, {"verify-delaunay", dir.file("points.txt"), dir.file("out.off")});
    CHECK(verified.exit_code == 0);
    CHECK(verified.out.rfind("ok: 60 points", 0) == 0);
    CHECK(count_of(verified.out, "\n") == 1);
}

TEST_CASE("delaunay cli: x y lines, x y z lines, rbox and standard input give the same triangles") {
    TempDir dir("hullkit-delaunay-cli");
    const Points xy = uniform_points(40, 5);
    write_text(dir.file("xy.txt"), xy_lines(xy));
    std::string xyz = "# x y z: z is ignored\n";
    for (std::size_t i = 0; i < xy.size(); i += 2) {
        xyz += hullkit::format_double(xy[i]) + " " + hullkit::format_double(xy[i + 1]) + " " + std::to_string(i) + "\n";
    }
    write_text(dir.file("xyz.txt"), xyz);
    write_text(dir.file("rbox.txt"), rbox_text(xy));
    const RunResult a = run_cli(dir, {"delaunay", dir.file("xy.txt")});
    const RunResult b = run_cli(dir, {"delaunay", dir.file("xyz.txt")});
    const RunResult c = run_cli(dir, {"delaunay", "-"}, dir.file("rbox.txt"));
    const RunResult d = run_cli(dir, {"delaunay"}, dir.file("xy.txt"));
    REQUIRE(a.exit_code == 0);
    CHECK(b.out == a.out);
    CHECK(c.out == a.out);
    CHECK(d.out == a.out);
}

TEST_CASE("delaunay cli: JSON output matches the OFF output and is a consistent half-edge structure") {
    TempDir dir("hullkit-delaunay-cli");
    Points xy = uniform_points(50, 23);
    // Two exact duplicates: point 50 repeats point 3, point 51 repeats point 7.
    xy.insert(xy.end(), {xy[6], xy[7], xy[14], xy[15]});
    write_text(dir.file("points.txt"), xy_lines(xy));
    const RunResult off = run_cli(dir, {"delaunay", dir.file("points.txt")});
    const RunResult run = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json"});
    REQUIRE(off.exit_code == 0);
    REQUIRE(run.exit_code == 0);
    const nlohmann::json json = nlohmann::json::parse(run.out);
    CHECK(json["dimension"] == 2);

    Points written;
    std::vector<std::uint32_t> off_triangles;
    read_delaunay_off(off.out, &written, &off_triangles);
    std::vector<std::uint32_t> triangles;
    for (const auto& triangle : json["triangles"]) {
        REQUIRE(triangle.size() == 3);
        for (const auto& index : triangle) triangles.push_back(index.get<std::uint32_t>());
    }
    CHECK(triangles == off_triangles);
    CHECK(join(brute_force_problems(xy, triangles)).empty());

    // halfedges: symmetric, each pair joins the same two points in opposite directions; -1 on the hull.
    const std::vector<std::int64_t> halfedges = json["halfedges"].get<std::vector<std::int64_t>>();
    REQUIRE(halfedges.size() == triangles.size());
    auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    std::map<std::uint32_t, std::uint32_t> hull_next;
    for (std::size_t e = 0; e < halfedges.size(); ++e) {
        if (halfedges[e] < 0) {
            hull_next[triangles[e]] = triangles[next(e)];
            continue;
        }
        const std::size_t o = static_cast<std::size_t>(halfedges[e]);
        REQUIRE(o < halfedges.size());
        CHECK(halfedges[o] == static_cast<std::int64_t>(e));
        CHECK(triangles[o] == triangles[next(e)]);
        CHECK(triangles[next(o)] == triangles[e]);
    }
    // hull: the cycle of the boundary half-edges, which is the exact convex hull.
    const std::vector<std::uint32_t> hull = json["hull"].get<std::vector<std::uint32_t>>();
    REQUIRE(hull.size() == hull_next.size());
    for (std::size_t k = 0; k < hull.size(); ++k) CHECK(hull_next.at(hull[k]) == hull[(k + 1) % hull.size()]);
    CHECK(std::set<std::size_t>(hull.begin(), hull.end()) ==
          [&] { auto h = exact_hull(xy); return std::set<std::size_t>(h.begin(), h.end()); }());

    // duplicates: [index, lowest index with the same coordinates]
    CHECK(json["duplicates"] == nlohmann::json::parse("[[50,3],[51,7]]"));
    CHECK(!json.contains("polygons"));
}

TEST_CASE("delaunay cli: --merge-cocircular reports the grid's squares") {
    TempDir dir("hullkit-delaunay-cli");
    const Points xy = grid_points(4);  // 9 unit squares
    write_text(dir.file("grid.txt"), xy_lines(xy));
    const RunResult run = run_cli(dir, {"delaunay", dir.file("grid.txt"), "--format=json", "--merge-cocircular"});
    REQUIRE(run.exit_code == 0);
    const nlohmann::json json = nlohmann::json::parse(run.out);
    REQUIRE(json.contains("polygons"));
    REQUIRE(json["polygons"].size() == 9);
    std::vector<std::uint32_t> triangles;
    for (const auto& triangle : json["triangles"]) {
        for (const auto& index : triangle) triangles.push_back(index.get<std::uint32_t>());
    }
    CHECK(triangles.size() == 3 * 18);
    CHECK(join(brute_force_problems(xy, triangles)).empty());
    for (const auto& polygon : json["polygons"]) {
        REQUIRE(polygon.size() == 4);
        // A unit square of the grid: its corners' x and y span exactly 1.
        double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
        for (const auto& index : polygon) {
            const std::size_t i = index.get<std::size_t>();
            xmin = std::min(xmin, xy[2 * i]);
            xmax = std::max(xmax, xy[2 * i]);
            ymin = std::min(ymin, xy[2 * i + 1]);
            ymax = std::max(ymax, xy[2 * i + 1]);
        }
        CHECK(xmax - xmin == 1.0);
        CHECK(ymax - ymin == 1.0);
    }
}

TEST_CASE("delaunay cli: --voronoi in JSON gives a grid's diagram exactly: a vertex per square, unit cells inside") {
    TempDir dir("hullkit-delaunay-cli");
    Points xy = grid_points(5);  // 16 unit squares; points 6-8, 11-13, 16-18 are inside
    xy.insert(xy.end(), {2.0, 2.0});  // point 25 repeats point 12
    write_text(dir.file("grid.txt"), xy_lines(xy));
    const RunResult run = run_cli(dir, {"delaunay", dir.file("grid.txt"), "--format", "json", "--voronoi"});
    REQUIRE(run.exit_code == 0);
    const nlohmann::json v = nlohmann::json::parse(run.out).at("voronoi");
    // One vertex per square, at its centre exactly.
    std::set<std::pair<double, double>> centres;
    for (const auto& vertex : v["vertices"]) centres.insert({vertex[0].get<double>(), vertex[1].get<double>()});
    CHECK(v["vertices"].size() == 16);
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) CHECK(centres.count({j + 0.5, i + 0.5}) == 1);
    }
    CHECK(v["triangle_vertex"].size() == 32);
    // A ridge per grid edge (the squares' diagonals are not Delaunay edges of the merged diagram).
    REQUIRE(v["ridge_points"].size() == 40);
    REQUIRE(v["ridge_vertices"].size() == 40);
    for (std::size_t r = 0; r < 40; ++r) {
        const std::size_t p = v["ridge_points"][r][0], q = v["ridge_points"][r][1];
        CHECK(std::abs(xy[2 * p] - xy[2 * q]) + std::abs(xy[2 * p + 1] - xy[2 * q + 1]) == 1.0);
        const int a = v["ridge_vertices"][r][0], b = v["ridge_vertices"][r][1];
        CHECK(b >= 0);
        CHECK(a >= -1);
    }
    REQUIRE(v["cells"].size() == 26);
    REQUIRE(v["area"].size() == 26);
    for (std::size_t i = 0; i < 25; ++i) {
        INFO("point " << i);
        const auto& cell = v["cells"][i];
        const double x = xy[2 * i], y = xy[2 * i + 1];
        const bool inside = x > 0 && x < 4 && y > 0 && y < 4;
        if (inside) {
            // The unit square around the point, counter-clockwise, from its lowest vertex.
            REQUIRE(cell.size() == 4);
            CHECK(v["area"][i].get<double>() == 1.0);
            double twice_area = 0;
            for (std::size_t k = 0; k < 4; ++k) {
                const auto& a = v["vertices"][cell[k].get<std::size_t>()];
                const auto& b = v["vertices"][cell[(k + 1) % 4].get<std::size_t>()];
                CHECK(std::abs(a[0].get<double>() - x) == 0.5);
                CHECK(std::abs(a[1].get<double>() - y) == 0.5);
                twice_area += a[0].get<double>() * b[1].get<double>() - a[1].get<double>() * b[0].get<double>();
            }
            CHECK(twice_area == 2.0);
        } else {
            REQUIRE(!cell.empty());
            CHECK(cell.back() == -1);
            CHECK(v["area"][i].is_null());
        }
    }
    CHECK(v["cells"][25].empty());
    CHECK(v["area"][25].is_null());
}

TEST_CASE("delaunay cli: --voronoi in JSON on random points: nearest-point vertices, Delaunay ridges, areas that add up") {
    TempDir dir("hullkit-delaunay-cli");
    const Points xy = uniform_points(300, 41);
    write_text(dir.file("points.txt"), xy_lines(xy));
    const RunResult run = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json", "--voronoi", "--threads", "1"});
    REQUIRE(run.exit_code == 0);
    const nlohmann::json json = nlohmann::json::parse(run.out);
    const nlohmann::json& v = json["voronoi"];
    // The same diagram on two threads.
    const RunResult two = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json", "--voronoi", "--threads", "2"});
    CHECK(two.out == run.out);
    // Ridges are exactly the triangulation's edges (general position: no cocircular merging).
    std::set<std::pair<std::size_t, std::size_t>> edges, ridges;
    for (const auto& t : json["triangles"]) {
        for (int k = 0; k < 3; ++k) {
            const std::size_t a = t[k], b = t[(k + 1) % 3];
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    }
    for (const auto& r : v["ridge_points"]) ridges.insert({r[0].get<std::size_t>(), r[1].get<std::size_t>()});
    CHECK(ridges == edges);
    CHECK(v["vertices"].size() == json["triangles"].size());
    const std::size_t n = xy.size() / 2;
    REQUIRE(v["cells"].size() == n);
    const std::vector<std::uint32_t> hull = json["hull"].get<std::vector<std::uint32_t>>();
    const std::set<std::uint32_t> on_hull(hull.begin(), hull.end());
    std::size_t bounded = 0;
    for (std::size_t i = 0; i < n; ++i) {
        INFO("point " << i);
        const auto& cell = v["cells"][i];
        REQUIRE(cell.size() >= 3);
        CHECK((cell.back() == -1) == (on_hull.count(static_cast<std::uint32_t>(i)) == 1));
        double twice_area = 0;
        const std::size_t corners = cell.back() == -1 ? cell.size() - 1 : cell.size();
        for (std::size_t k = 0; k < corners; ++k) {
            // Every corner of the cell is at least as near to this point as to any other (to rounding).
            const auto& a = v["vertices"][cell[k].get<std::size_t>()];
            const double ax = a[0], ay = a[1];
            const double mine = std::hypot(ax - xy[2 * i], ay - xy[2 * i + 1]);
            double nearest = mine;
            for (std::size_t q = 0; q < n; ++q) nearest = std::min(nearest, std::hypot(ax - xy[2 * q], ay - xy[2 * q + 1]));
            CHECK(mine <= nearest * (1 + 1e-9) + 1e-12);
            const auto& b = v["vertices"][cell[(k + 1) % corners].get<std::size_t>()];
            twice_area += ax * b[1].get<double>() - ay * b[0].get<double>();
        }
        if (cell.back() != -1) {
            ++bounded;
            CHECK(twice_area > 0);  // counter-clockwise
            CHECK(v["area"][i].get<double>() == Approx(twice_area / 2).epsilon(1e-9));
        } else {
            CHECK(v["area"][i].is_null());
        }
    }
    CHECK(bounded == n - hull.size());
}

TEST_CASE("delaunay cli: --algorithm giftwrap writes the same triangulation as the default") {
    TempDir dir("hullkit-delaunay-cli");
    Points xy = uniform_points(30, 3);
    const Points grid = grid_points(3);
    xy.insert(xy.end(), grid.begin(), grid.end());  // cocircular points as well
    write_text(dir.file("points.txt"), xy_lines(xy));
    const RunResult incremental = run_cli(dir, {"delaunay", dir.file("points.txt"), "--algorithm", "incremental"});
    const RunResult giftwrap = run_cli(dir, {"delaunay", dir.file("points.txt"), "--algorithm=giftwrap"});
    const RunResult plain = run_cli(dir, {"delaunay", dir.file("points.txt")});
    REQUIRE(incremental.exit_code == 0);
    REQUIRE(giftwrap.exit_code == 0);
    CHECK(plain.out == incremental.out);
    Points written;
    std::vector<std::uint32_t> a, b;
    read_delaunay_off(incremental.out, &written, &a);
    read_delaunay_off(giftwrap.out, &written, &b);
    CHECK(canonical(a) == canonical(b));
    CHECK(join(brute_force_problems(xy, b)).empty());
}

TEST_CASE("delaunay cli: SVG output is well-formed and draws every edge, the hull and the Voronoi cells") {
    TempDir dir("hullkit-delaunay-cli");
    const Points xy = uniform_points(25, 8);
    write_text(dir.file("points.txt"), xy_lines(xy));
    const RunResult json_run = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json"});
    REQUIRE(json_run.exit_code == 0);
    const nlohmann::json json = nlohmann::json::parse(json_run.out);
    const std::size_t triangles = json["triangles"].size(), hull = json["hull"].size();

    const RunResult plain = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "svg"});
    REQUIRE(plain.exit_code == 0);
    CHECK(xml_problem(plain.out).empty());
    CHECK(plain.out.find("<svg xmlns=\"http://www.w3.org/2000/svg\"") != std::string::npos);
    // Edges: E = 3T/2 + H/2 (each interior edge once, each hull edge once), one "M" each.
    CHECK(count_of(plain.out, "M") == (3 * triangles + hull) / 2);
    CHECK(count_of(plain.out, "<circle") == 25);
    CHECK(count_of(plain.out, "id=\"hull\"") == 1);
    CHECK(count_of(plain.out, "id=\"voronoi\"") == 0);

    const RunResult cells = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "svg", "--voronoi"});
    REQUIRE(cells.exit_code == 0);
    CHECK(xml_problem(cells.out).empty());
    CHECK(count_of(cells.out, "id=\"voronoi\"") == 1);
    // The picture contains every point, so every point's cell meets it.
    CHECK(count_of(cells.out, "<polygon points=") == 25);
}

TEST_CASE("delaunay cli: -o picks the format from the extension unless --format is given") {
    TempDir dir("hullkit-delaunay-cli");
    write_text(dir.file("points.txt"), xy_lines(uniform_points(12, 4)));
    for (const char* name : {"out.json", "out.JSON", "out.svg", "out.off", "out.txt"}) {
        const RunResult run = run_cli(dir, {"delaunay", dir.file("points.txt"), "-o", dir.file(name)});
        REQUIRE(run.exit_code == 0);
        CHECK(run.out.empty());
        const std::string text = read_text(dir.file(name));
        const std::string ext = name + 4;
        if (ext == "json" || ext == "JSON") CHECK(text.rfind("{\"dimension\":2", 0) == 0);
        else if (ext == "svg") CHECK(text.rfind("<?xml", 0) == 0);
        else CHECK(text.rfind("OFF\n", 0) == 0);
    }
    const RunResult forced = run_cli(dir, {"delaunay", dir.file("points.txt"), "--output", dir.file("x.json"), "--format", "off"});
    REQUIRE(forced.exit_code == 0);
    CHECK(read_text(dir.file("x.json")).rfind("OFF\n", 0) == 0);
    // The last of a repeated option wins, as for `hullkit hull`.
    const RunResult twice = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "svg", "--format", "json"});
    CHECK(twice.out.rfind("{\"dimension\"", 0) == 0);
}

TEST_CASE("delaunay cli: --stats writes one JSON line about the computation") {
    TempDir dir("hullkit-delaunay-cli");
    Points xy = uniform_points(100, 9);
    xy.insert(xy.end(), {xy[0], xy[1]});  // a duplicate counts as an input point
    write_text(dir.file("points.txt"), xy_lines(xy));
    const RunResult json_run = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json"});
    const nlohmann::json json = nlohmann::json::parse(json_run.out);
    for (const char* algorithm : {"incremental", "giftwrap"}) {
        const RunResult run = run_cli(dir, {"delaunay", dir.file("points.txt"), "--stats", "--algorithm", algorithm});
        REQUIRE(run.exit_code == 0);
        REQUIRE(run.err_lines().size() == 1);
        const nlohmann::json stats = nlohmann::json::parse(run.err);
        CHECK(stats["points"] == 101);
        CHECK(stats["triangles"] == json["triangles"].size());
        CHECK(stats["hull"] == json["hull"].size());
        CHECK(stats["algorithm"] == algorithm);
        CHECK(stats["seconds"].get<double>() >= 0.0);
        CHECK(stats["seconds"].get<double>() < 60.0);
        CHECK(stats.size() == 5);
    }
}

TEST_CASE("delaunay cli: collinear and tiny inputs give no triangles, not an error") {
    TempDir dir("hullkit-delaunay-cli");
    const std::vector<std::pair<std::string, int>> cases = {
        {"0 0\n1 1\n2 2\n3 3\n", 1}, {"5 5\n", 0}, {"1 2\n1 2\n", 0}, {"0 0\n1 0\n", 1}};
    for (const auto& [text, dimension] : cases) {
        INFO(text);
        write_text(dir.file("points.txt"), text);
        const RunResult json_run = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json"});
        REQUIRE(json_run.exit_code == 0);
        const nlohmann::json json = nlohmann::json::parse(json_run.out);
        CHECK(json["dimension"] == dimension);
        CHECK(json["triangles"].empty());
        const RunResult off = run_cli(dir, {"delaunay", dir.file("points.txt"), "-o", dir.file("out.off")});
        REQUIRE(off.exit_code == 0);
        const RunResult svg = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "svg", "--voronoi"});
        REQUIRE(svg.exit_code == 0);
        CHECK(xml_problem(svg.out).empty());
        // The diagram of collinear points: a ray-only ridge between neighbours, every cell unbounded.
        const nlohmann::json v = nlohmann::json::parse(run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json", "--voronoi"}).out)["voronoi"];
        CHECK(v["vertices"].empty());
        for (const auto& r : v["ridge_vertices"]) CHECK(r == nlohmann::json::parse("[-1,-1]"));
        CHECK(v["ridge_points"].size() == (dimension == 1 ? v["cells"].size() - 1 : 0));
        for (const auto& a : v["area"]) CHECK(a.is_null());
    }
    // Collinear points: the hull lists them in order along the line.
    write_text(dir.file("points.txt"), "2 2\n0 0\n3 3\n1 1\n");
    const nlohmann::json json = nlohmann::json::parse(run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "json"}).out);
    const std::vector<std::uint32_t> hull = json["hull"].get<std::vector<std::uint32_t>>();
    CHECK((hull == std::vector<std::uint32_t>{1, 3, 0, 2} || hull == std::vector<std::uint32_t>{2, 0, 3, 1}));
}

TEST_CASE("delaunay cli: usage and input errors are one line with exit status 2") {
    TempDir dir("hullkit-delaunay-cli");
    write_text(dir.file("points.txt"), "0 0\n1 0\n0 1\n");
    const std::string points = dir.file("points.txt");
    require_usage_error(run_cli(dir, {"delaunay", points, "--frobnicate"}), "unknown option \"--frobnicate\"");
    require_usage_error(run_cli(dir, {"delaunay", points, "other.txt"}), "unexpected argument \"other.txt\"");
    require_usage_error(run_cli(dir, {"delaunay", points, "--format"}), "option --format needs a value");
    require_usage_error(run_cli(dir, {"delaunay", points, "--format", "ply"}), "unknown format \"ply\" (known: off, json, svg)");
    require_usage_error(run_cli(dir, {"delaunay", points, "--algorithm", "quickhull"}),
                        "unknown algorithm \"quickhull\" (known: incremental, giftwrap)");
    require_usage_error(run_cli(dir, {"delaunay", points, "-o"}), "needs a value");
    require_usage_error(run_cli(dir, {"delaunay", points, "-o", ""}), "needs a file name");
    require_usage_error(run_cli(dir, {"delaunay", points, "--voronoi"}), "--voronoi adds the Voronoi diagram to JSON output or draws its cells in SVG, not in OFF");
    require_usage_error(run_cli(dir, {"delaunay", dir.file("missing.txt")}), "missing.txt: cannot open");
    require_usage_error(run_cli(dir, {"delaunay", points, "-o", dir.file("no/such/dir/out.off")}), "cannot open for writing");

    const std::vector<std::pair<std::string, std::string>> inputs = {
        {"0 0\n1 0\n0 1x\n", "points.txt:3: coordinate \"1x\" of point 2 is not a finite number"},
        {"0 0\n# comment\n\n1 nan\n", "points.txt:4: coordinate \"nan\" of point 1 is not a finite number"},
        {"0 0\n1 inf\n", "points.txt:2: coordinate \"inf\" of point 1 is not a finite number"},
        {"0 0\n1 2 3\n", "points.txt:2: expected 2 coordinates, got 3"},
        {"0 0 0 0\n", "points.txt:1: expected 2 coordinates (x y) or 3"},
        {"2\n3\n0 0\n1 1\n", "points.txt:2: header declares 3 points but the file has 2"},
        {"2\n1\n0 0\n1 1\n", "points.txt:4: more points than the 1 declared on line 2"},
        {"4\n1\n0 0 0 0\n", "points.txt:1: dimension is 4, expected 2"},
        {"2\nmany\n", "points.txt:2: expected the point count"},
        {"0 0\n1 1e400\n", "points.txt:2: coordinate \"1e400\" of point 1 is out of the double range"},
        {"x,y\n0,0\n1,,2\n", "points.txt:3: empty field before a comma"},
    };
    for (const auto& [text, message] : inputs) {
        INFO(text);
        write_text(points, text);
        require_usage_error(run_cli(dir, {"delaunay", points}), message);
    }
    // The same problem on standard input is named "<stdin>".
    write_text(points, "0 0\n1 nan\n");
    require_usage_error(run_cli(dir, {"delaunay"}, points), "<stdin>:2: coordinate \"nan\" of point 1 is not a finite number");
    // Magnitudes the exact predicates cannot take even after rescaling: the core names the point,
    // the command adds its line.
    write_text(points, "0 0\n1e-300 1\n1e300 1\n");
    const RunResult range = run_cli(dir, {"delaunay", points});
    require_usage_error(range, "points.txt:");
    CHECK((range.err.find("points.txt:2:") != std::string::npos || range.err.find("points.txt:3:") != std::string::npos));
}

TEST_CASE("delaunay cli: no points is an empty triangulation (dimension -1), exit 0") {
    TempDir dir("hullkit-delaunay-cli");
    for (const std::string text : {"", "# nothing\n\n", "2 rbox 0 D2\n0\n", "x,y\n"}) {
        INFO(text);
        write_text(dir.file("points.txt"), text);
        const RunResult off = run_cli(dir, {"delaunay", dir.file("points.txt")});
        CHECK(off.exit_code == 0);
        CHECK(off.out == "OFF\n0 0 0\n");
        const RunResult json = run_cli(dir, {"delaunay", "--format", "json", "--quiet"}, dir.file("points.txt"));
        CHECK(json.exit_code == 0);
        CHECK(json.err.empty());
        CHECK(json.out == "{\"dimension\":-1,\"triangles\":[],\"halfedges\":[],\"hull\":[],\"duplicates\":[]}\n");
        const RunResult svg = run_cli(dir, {"delaunay", dir.file("points.txt"), "--format", "svg"});
        CHECK(svg.exit_code == 0);
        CHECK_THAT(svg.out, Catch::Contains("0 points, 0 triangles"));
    }
}

TEST_CASE("delaunay cli: CSV with a header row and a byte-order mark is read") {
    TempDir dir("hullkit-delaunay-cli");
    write_text(dir.file("plain.txt"), "0 0\n1 0\n0 1\n1 1.5\n");
    write_text(dir.file("points.csv"), "\xEF\xBB\xBFx,y\n0,0\n1, 0\n0 ,1\n1,1.5\n");
    const RunResult plain = run_cli(dir, {"delaunay", dir.file("plain.txt")});
    const RunResult csv = run_cli(dir, {"delaunay", dir.file("points.csv")});
    REQUIRE(csv.exit_code == 0);
    CHECK(csv.out == plain.out);
    CHECK(csv.err == "hullkit: warning: " + dir.file("points.csv") + ": skipped header line 1: x,y\n");
    CHECK(run_cli(dir, {"delaunay", dir.file("points.csv"), "--quiet"}).err.empty());
}

TEST_CASE("delaunay cli: --help describes the command and exits 0") {
    TempDir dir("hullkit-delaunay-cli");
    const RunResult run = run_cli(dir, {"delaunay", "--help"});
    CHECK(run.exit_code == 0);
    CHECK(run.out.rfind("Usage: hullkit delaunay", 0) == 0);
    CHECK(run.out.find("incremental (default), giftwrap") != std::string::npos);
    const RunResult verify = run_cli(dir, {"verify-delaunay", "-h"});
    CHECK(verify.exit_code == 0);
    CHECK(verify.out.rfind("Usage: hullkit verify-delaunay", 0) == 0);
}

TEST_CASE("verify-delaunay cli: tells the Delaunay diagonal of a quadrilateral from the other one") {
    TempDir dir("hullkit-delaunay-cli");
    // A convex quadrilateral, counter-clockwise, not cocircular: exactly one diagonal is Delaunay.
    const Points xy = {0, 0, 3, 0, 3, 3, 0, 1};
    write_text(dir.file("quad.txt"), xy_lines(xy));
    const std::string vertices = "OFF\n4 2 0\n0 0 0\n3 0 0\n3 3 0\n0 1 0\n";
    const std::vector<std::uint32_t> diagonal_ac = {0, 2, 1, 0, 3, 2}, diagonal_bd = {0, 3, 1, 1, 3, 2};
    int delaunay_count = 0;
    for (const auto& triangles : {diagonal_ac, diagonal_bd}) {
        write_text(dir.file("quad.off"), vertices + "3 " + std::to_string(triangles[0]) + " " + std::to_string(triangles[1]) +
                                             " " + std::to_string(triangles[2]) + "\n3 " + std::to_string(triangles[3]) + " " +
                                             std::to_string(triangles[4]) + " " + std::to_string(triangles[5]) + "\n");
        const bool brute_force_ok = brute_force_problems(xy, triangles).empty();
        const RunResult run = run_cli(dir, {"verify-delaunay", dir.file("quad.txt"), dir.file("quad.off")});
        INFO(run.out << run.err);
        CHECK(run.exit_code == (brute_force_ok ? 0 : 1));
        if (!brute_force_ok) CHECK(run.out.find("not a Delaunay triangulation") != std::string::npos);
        delaunay_count += brute_force_ok;
    }
    CHECK(delaunay_count == 1);
}

TEST_CASE("verify-delaunay cli: the triangulation in any mesh format (OBJ here), as hullkit verify reads hulls") {
    TempDir dir("hullkit-delaunay-cli");
    const Points xy = uniform_points(50, 9);
    write_text(dir.file("points.txt"), xy_lines(xy));
    const hullkit::MeshResult off = hullkit::read_off_mesh(run_cli(dir, {"delaunay", dir.file("points.txt")}).out, "t.off");
    REQUIRE(off.ok());
    std::string obj;
    for (std::size_t k = 0; k < off.point_count(); ++k) {
        obj += "v " + hullkit::format_double(off.xyz[3 * k]) + " " + hullkit::format_double(off.xyz[3 * k + 1]) + " 0\n";
    }
    for (std::size_t t = 0; t < off.triangle_count(); ++t) {
        obj += "f " + std::to_string(off.triangles[3 * t] + 1) + " " + std::to_string(off.triangles[3 * t + 1] + 1) + " " +
               std::to_string(off.triangles[3 * t + 2] + 1) + "\n";
    }
    write_text(dir.file("t.obj"), obj);
    const RunResult run = run_cli(dir, {"verify-delaunay", dir.file("points.txt"), dir.file("t.obj")});
    INFO(run.out << run.err);
    CHECK(run.exit_code == 0);
    CHECK(run.out.rfind("ok: 50 points", 0) == 0);
}

TEST_CASE("verify-delaunay cli: problems are lines on stdout with exit status 1") {
    TempDir dir("hullkit-delaunay-cli");
    const Points xy = uniform_points(20, 2);
    write_text(dir.file("points.txt"), xy_lines(xy));
    const std::string off = run_cli(dir, {"delaunay", dir.file("points.txt")}).out;

    // A vertex moved off the input points.
    std::string moved = off;
    const std::size_t line = moved.find('\n', moved.find('\n') + 1) + 1;  // the first vertex line
    moved.replace(line, moved.find(' ', line) - line, "12345");
    write_text(dir.file("moved.off"), moved);
    RunResult run = run_cli(dir, {"verify-delaunay", dir.file("points.txt"), dir.file("moved.off")});
    CHECK(run.exit_code == 1);
    CHECK(run.out.find(": vertex 0 (12345 ") != std::string::npos);
    CHECK(run.out.find("is not one of the input points") != std::string::npos);

    // A triangle dropped: a point no longer used, the hull no longer covered.
    std::string dropped = off.substr(0, off.rfind("\n3 ") + 1);
    const std::size_t counts = dropped.find('\n') + 1;
    Points written;
    std::vector<std::uint32_t> triangles;
    read_delaunay_off(off, &written, &triangles);
    dropped.replace(counts, dropped.find('\n', counts) - counts,
                    "20 " + std::to_string(triangles.size() / 3 - 1) + " 0");
    write_text(dir.file("dropped.off"), dropped);
    run = run_cli(dir, {"verify-delaunay", dir.file("points.txt"), dir.file("dropped.off")});
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("not a Delaunay triangulation") != std::string::npos);

    // A triangle reversed (counter-clockwise).
    std::string reversed = off;
    const std::size_t last = reversed.rfind("\n3 ") + 1;
    std::istringstream fields(reversed.substr(last));
    int three;
    std::uint32_t a, b, c;
    fields >> three >> a >> b >> c;
    reversed.replace(last, std::string::npos, "3 " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + "\n");
    write_text(dir.file("reversed.off"), reversed);
    run = run_cli(dir, {"verify-delaunay", dir.file("points.txt"), dir.file("reversed.off")});
    CHECK(run.exit_code == 1);
}

TEST_CASE("verify-delaunay cli: usage and input errors exit 2") {
    TempDir dir("hullkit-delaunay-cli");
    write_text(dir.file("points.txt"), "0 0\n1 0\n0 1\n");
    write_text(dir.file("ok.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 2 1\n");
    write_text(dir.file("bad.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 2 7\n");
    const std::string points = dir.file("points.txt");
    CHECK(run_cli(dir, {"verify-delaunay", points, dir.file("ok.off")}).exit_code == 0);
    require_usage_error(run_cli(dir, {"verify-delaunay", points}), "needs two files");
    require_usage_error(run_cli(dir, {"verify-delaunay", points, dir.file("ok.off"), points}), "needs two files, POINTS and TRIANGLES, got 3");
    require_usage_error(run_cli(dir, {"verify-delaunay", "--strict", points, dir.file("ok.off")}), "unknown option \"--strict\"");
    require_usage_error(run_cli(dir, {"verify-delaunay", points, "-"}), "TRIANGLES must be a file");
    require_usage_error(run_cli(dir, {"verify-delaunay", points, dir.file("missing.off")}), "missing.off: cannot open");
    require_usage_error(run_cli(dir, {"verify-delaunay", points, dir.file("bad.off")}), "bad.off:");
    require_usage_error(run_cli(dir, {"verify-delaunay", points, points}), "points.txt:");
    write_text(dir.file("nan.txt"), "0 0\nnan 1\n");
    require_usage_error(run_cli(dir, {"verify-delaunay", dir.file("nan.txt"), dir.file("ok.off")}), "nan.txt:2:");
    // POINTS from standard input.
    CHECK(run_cli(dir, {"verify-delaunay", "-", dir.file("ok.off")}, points).exit_code == 0);
}
