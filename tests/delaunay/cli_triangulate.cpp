// Tests of `hullkit triangulate` (the built binary): every input format and output format, checked
// independently of the library (JSON parsed; triangle orientation and area with GMP rationals;
// Triangle's .node/.ele re-read), and the error paths naming the line.
#include <catch2/catch.hpp>
#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cli/cli_support.hpp"

namespace {

using hullkit_test::RunResult;
using hullkit_test::TempDir;
using hullkit_test::read_text;
using hullkit_test::run_cli;
using hullkit_test::write_text;

const char* const kSquareWithHole = "# outline\n0 0\n4 0\n4 4\n0 4\n\n# hole\n1 1\n3 1\n3 3\n1 3\n";

const char* const kSquareWithHolePoly =
    "8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 1\n7 3 3\n8 1 3\n"
    "8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n1\n1 2 2\n";

/// The JSON output parsed, with every triangle checked clockwise (y up) and the total area returned (exact).
mpq_class checked_area(const nlohmann::json& j) {
    mpq_class sum = 0;
    for (const auto& t : j["triangles"]) {
        const auto& a = j["points"][t[0].get<std::size_t>()];
        const auto& b = j["points"][t[1].get<std::size_t>()];
        const auto& c = j["points"][t[2].get<std::size_t>()];
        const mpq_class cross = (mpq_class(b[0].get<double>()) - a[0].get<double>()) * (mpq_class(c[1].get<double>()) - a[1].get<double>()) -
                                (mpq_class(b[1].get<double>()) - a[1].get<double>()) * (mpq_class(c[0].get<double>()) - a[0].get<double>());
        REQUIRE(cross < 0);
        sum -= cross;
    }
    REQUIRE(j["halfedges"].size() == 3 * j["triangles"].size());
    REQUIRE(j["constrained"].size() == 3 * j["triangles"].size());
    return sum / 2;
}

nlohmann::json json_of(const RunResult& run) {
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    return nlohmann::json::parse(run.out);
}

}  // namespace

TEST_CASE("hullkit triangulate: x y rings, GeoJSON and .poly give the square with a hole", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    write_text(dir.file("rings.txt"), kSquareWithHole);
    const nlohmann::json rings = json_of(run_cli(dir, {"triangulate", dir.file("rings.txt"), "--format", "json"}));
    CHECK(checked_area(rings) == 12);
    CHECK(rings["triangles"].size() == 8);
    CHECK(rings["added"] == 0);
    // nonzero: the hole wound like the outline is filled.
    CHECK(checked_area(json_of(run_cli(dir, {"triangulate", dir.file("rings.txt"), "--format", "json", "--fill", "nonzero"}))) == 16);

    write_text(dir.file("square.geojson"),
               R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":)"
               R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1,1],[1,3],[3,3],[3,1],[1,1]]]}}]})");
    CHECK(checked_area(json_of(run_cli(dir, {"triangulate", dir.file("square.geojson"), "--format", "json"}))) == 12);

    write_text(dir.file("square.poly"), kSquareWithHolePoly);
    const nlohmann::json poly = json_of(run_cli(dir, {"triangulate", dir.file("square.poly"), "--format", "json"}));
    CHECK(checked_area(poly) == 12);
    // Without the hole point the hole is meshed too; --convex keeps the exterior (none here).
    std::string no_hole = kSquareWithHolePoly;
    no_hole.replace(no_hole.rfind("1\n1 2 2\n"), 8, "0\n");
    write_text(dir.file("filled.poly"), no_hole);
    CHECK(checked_area(json_of(run_cli(dir, {"triangulate", dir.file("filled.poly"), "--format", "json"}))) == 16);
}

TEST_CASE("hullkit triangulate: .poly removes the exterior unless --convex", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    // An L-shaped outline: its convex hull has a notch outside the segments.
    write_text(dir.file("l.poly"), "6 2 0 0\n0 0 0\n1 2 0\n2 2 1\n3 1 1\n4 1 2\n5 0 2\n6 0\n0 0 1\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 0\n0\n");
    CHECK(checked_area(json_of(run_cli(dir, {"triangulate", dir.file("l.poly"), "--format", "json"}))) == 3);
    mpq_class hull_area = checked_area(json_of(run_cli(dir, {"triangulate", dir.file("l.poly"), "--format", "json", "--convex"})));
    CHECK(hull_area == mpq_class(7, 2));
}

TEST_CASE("hullkit triangulate: a bow-tie's crossing is added, every output format", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    write_text(dir.file("bowtie.txt"), "0 0\n2 2\n2 0\n0 2\n");
    const RunResult stats = run_cli(dir, {"triangulate", dir.file("bowtie.txt"), "--format", "json", "--stats"});
    const nlohmann::json j = json_of(stats);
    CHECK(j["added"] == 1);
    CHECK(j["points"][4] == nlohmann::json::array({1, 1}));
    CHECK(checked_area(j) == 2);
    const nlohmann::json line = nlohmann::json::parse(stats.err);
    CHECK(line["crossings"] == 1);
    CHECK(line["triangles"] == 2);

    const RunResult off = run_cli(dir, {"triangulate", dir.file("bowtie.txt")});
    REQUIRE(off.exit_code == 0);
    CHECK(off.out.rfind("OFF\n5 2 0\n", 0) == 0);
    REQUIRE(run_cli(dir, {"triangulate", dir.file("bowtie.txt"), "-o", dir.file("b.obj")}).exit_code == 0);
    const std::string obj = read_text(dir.file("b.obj"));
    CHECK(obj.find("v 1 1 0\n") != std::string::npos);
    CHECK(obj.find("f ") != std::string::npos);
    REQUIRE(run_cli(dir, {"triangulate", dir.file("bowtie.txt"), "-o", dir.file("b.svg")}).exit_code == 0);
    const std::string svg = read_text(dir.file("b.svg"));
    CHECK(svg.find("<svg") != std::string::npos);
    CHECK(svg.find("id=\"segments\"") != std::string::npos);
    CHECK(svg.find("</svg>") != std::string::npos);
    REQUIRE(run_cli(dir, {"triangulate", dir.file("bowtie.txt"), "-o", dir.file("b.ele")}).exit_code == 0);
    std::istringstream node(read_text(dir.file("b.node"))), ele(read_text(dir.file("b.ele")));
    std::size_t points = 0, triangles = 0, dim = 0, attributes = 0, markers = 0;
    node >> points >> dim >> attributes >> markers;
    ele >> triangles >> dim >> attributes;
    CHECK(points == 5);
    CHECK(triangles == 2);
    // .ele triangles are counter-clockwise (Triangle's convention) with 1-based vertices.
    std::vector<double> xy;
    for (std::size_t i = 0; i < points; ++i) {
        double index, x, y;
        node >> index >> x >> y;
        xy.push_back(x), xy.push_back(y);
    }
    for (std::size_t t = 0; t < triangles; ++t) {
        std::size_t index, a, b, c;
        ele >> index >> a >> b >> c;
        const double* p[3] = {&xy[2 * (a - 1)], &xy[2 * (b - 1)], &xy[2 * (c - 1)]};
        CHECK((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]) > 0);
    }
}

TEST_CASE("hullkit triangulate: errors name the file, line and ring", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    auto error_of = [&](const std::string& name, const std::string& text, std::vector<std::string> extra = {}) {
        write_text(dir.file(name), text);
        std::vector<std::string> args = {"triangulate", dir.file(name)};
        args.insert(args.end(), extra.begin(), extra.end());
        const RunResult run = run_cli(dir, args);
        CHECK(run.exit_code == 2);
        return run.err;
    };
    CHECK(error_of("bad.txt", "0 0\n1 x\n").find("bad.txt line 2: expected \"x y\"") != std::string::npos);
    CHECK(error_of("nan.txt", "0 0\n1 0\n\n5 5\nnan 1\n").find("nan.txt line 5 (ring 1, vertex 1): point 3 has a non-finite x") != std::string::npos);
    CHECK(error_of("bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 9\n").find("bad.poly line 6: segment vertex 9 is not one of the 3 vertices") !=
          std::string::npos);
    CHECK(error_of("line.geojson", R"({"type":"LineString","coordinates":[[0,0],[1,1]]})").find("LineString is not a Polygon") != std::string::npos);
    CHECK(error_of("ok.txt", "0 0\n1 0\n0 1\n", {"--fill", "winding"}).find("unknown fill rule \"winding\"") != std::string::npos);
    CHECK(error_of("ok2.txt", "0 0\n1 0\n0 1\n", {"--format", "node"}).find("give -o BASE.node") != std::string::npos);
    CHECK(error_of("regions.poly", std::string(kSquareWithHolePoly) + "1\n1 0.5 0.5\n").find("regions.poly line 22: expected \"index x y attribute") !=
          std::string::npos);
    CHECK(error_of("ok3.txt", "0 0\n1 0\n0 1\n", {"--min-angle", "35"}).find("--min-angle must be from 0 to 34") != std::string::npos);
    CHECK(error_of("ok4.txt", "0 0\n1 0\n0 1\n", {"--max-area", "-1"}).find("--max-area must be a positive number") != std::string::npos);
    CHECK(error_of("ok5.txt", "0 0\n1 0\n0 1\n", {"--max-area", "0.0001", "--max-steiner", "20"}).find("max_steiner_points") !=
          std::string::npos);
}

TEST_CASE("hullkit triangulate: quality meshes (--min-angle, --max-area, --conforming, .poly regions)", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    write_text(dir.file("rings.txt"), kSquareWithHole);
    // The smallest angle and the largest area, measured on the JSON output.
    auto measure = [](const nlohmann::json& j, double* smallest, double* largest) {
        *smallest = 180, *largest = 0;
        for (const auto& t : j["triangles"]) {
            double p[3][2];
            for (int k = 0; k < 3; ++k) p[k][0] = j["points"][t[k].get<std::size_t>()][0], p[k][1] = j["points"][t[k].get<std::size_t>()][1];
            for (int k = 0; k < 3; ++k) {
                const double ux = p[(k + 1) % 3][0] - p[k][0], uy = p[(k + 1) % 3][1] - p[k][1];
                const double vx = p[(k + 2) % 3][0] - p[k][0], vy = p[(k + 2) % 3][1] - p[k][1];
                *smallest = std::min(*smallest, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / M_PI);
                *largest = std::max(*largest, std::fabs(ux * vy - uy * vx) / 2);
            }
        }
    };
    double smallest, largest;
    const RunResult run = run_cli(dir, {"triangulate", dir.file("rings.txt"), "--format", "json", "--min-angle", "30", "--max-area", "0.5", "--stats"});
    const nlohmann::json mesh = json_of(run);
    CHECK(checked_area(mesh) == 12);  // exact: the added points on these rings are exact
    measure(mesh, &smallest, &largest);
    CHECK(smallest >= 30);
    CHECK(largest <= 0.5);
    const nlohmann::json stats = nlohmann::json::parse(run.err);
    CHECK(stats["steiner"].get<std::size_t>() == mesh["points"].size() - 8);
    CHECK(stats["unrefined"] == 0);
    // A .poly's regions: the area bound of the region around (0.5, 0.5) is the ring around the hole.
    write_text(dir.file("regions.poly"), std::string(kSquareWithHolePoly) + "1\n1 0.5 0.5 7 0.05\n");
    const nlohmann::json regional = json_of(run_cli(dir, {"triangulate", dir.file("regions.poly"), "--format", "json"}));
    CHECK(checked_area(regional) == 12);
    measure(regional, &smallest, &largest);
    CHECK(largest <= 0.05);
    // Conforming: more points than the constrained mesh, the same area.
    const nlohmann::json conforming = json_of(run_cli(dir, {"triangulate", dir.file("rings.txt"), "--format", "json", "--conforming", "--min-angle", "20"}));
    CHECK(checked_area(conforming) == 12);
}

TEST_CASE("hullkit triangulate: --region-attributes (Triangle's -A) in JSON and .ele, through refinement", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    // The square [0, 4]^2 split by the segment x = 2; region points (1, 1) attribute 5 and (3, 1)
    // attribute 9 with an area bound, so the right half is refined.
    write_text(dir.file("halves.poly"),
               "6 2 0 0\n1 0 0\n2 2 0\n3 4 0\n4 4 4\n5 2 4\n6 0 4\n"
               "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n2\n1 1 1 5\n2 3 1 9 0.25\n");
    for (const std::vector<std::string>& extra : {std::vector<std::string>{}, std::vector<std::string>{"--min-angle", "25"}}) {
        std::vector<std::string> args = {"triangulate", dir.file("halves.poly"), "--format", "json", "--region-attributes"};
        args.insert(args.end(), extra.begin(), extra.end());
        const nlohmann::json j = json_of(run_cli(dir, args));
        CHECK(checked_area(j) == 16);
        REQUIRE(j["attributes"].size() == j["triangles"].size());
        std::size_t left = 0, right = 0;
        for (std::size_t t = 0; t < j["triangles"].size(); ++t) {
            double cx = 0;
            for (int k = 0; k < 3; ++k) cx += j["points"][j["triangles"][t][k].get<std::size_t>()][0].get<double>() / 3;
            const double attribute = j["attributes"][t].get<double>();
            CHECK(attribute == (cx < 2 ? 5.0 : 9.0));
            (cx < 2 ? left : right) += 1;
        }
        CHECK(right > left);  // the area bound applies on the right only
    }
    // Triangle's .ele: one attribute column; no regions: zeros; a later seed in the same region wins.
    write_text(dir.file("same.poly"),
               "6 2 0 0\n1 0 0\n2 2 0\n3 4 0\n4 4 4\n5 2 4\n6 0 4\n"
               "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n2\n1 3 1 9\n2 3.5 3 -2.5\n");
    REQUIRE(run_cli(dir, {"triangulate", dir.file("same.poly"), "-o", dir.file("same.node"), "--region-attributes"}).exit_code == 0);
    std::istringstream ele(read_text(dir.file("same.ele")));
    std::size_t count = 0, corners = 0, attributes = 0;
    ele >> count >> corners >> attributes;
    REQUIRE(attributes == 1);
    std::size_t on_right = 0;
    for (std::size_t t = 0; t < count; ++t) {
        std::size_t index, a, b, c;
        double attribute;
        ele >> index >> a >> b >> c >> attribute;
        CHECK((attribute == 0 || attribute == -2.5));
        on_right += attribute == -2.5;
    }
    CHECK(on_right == 2);
    // Errors: not a .poly; a format without a place for them.
    write_text(dir.file("rings.txt"), kSquareWithHole);
    const RunResult rings = run_cli(dir, {"triangulate", dir.file("rings.txt"), "--format", "json", "--region-attributes"});
    CHECK(rings.exit_code == 2);
    CHECK(rings.err.find("--region-attributes needs a Triangle .poly input") != std::string::npos);
    const RunResult off = run_cli(dir, {"triangulate", dir.file("halves.poly"), "--region-attributes"});
    CHECK(off.exit_code == 2);
    CHECK(off.err.find("OFF, OBJ and SVG have no place") != std::string::npos);
}

TEST_CASE("hullkit triangulate: --keep-segments boundary|all (Triangle's -Y, -YY)", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    write_text(dir.file("halves.poly"),
               "6 2 0 0\n1 0 0\n2 2 0\n3 4 0\n4 4 4\n5 2 4\n6 0 4\n"
               "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n");
    // The segment edges (constrained half-edges, each edge once) along x = 0 and x = 2.
    auto pieces = [](const nlohmann::json& j, double x) {
        std::size_t count = 0;
        for (std::size_t e = 0; e < j["constrained"].size(); ++e) {
            const long twin = j["halfedges"][e].get<long>();
            if (j["constrained"][e] == 0 || (twin >= 0 && static_cast<std::size_t>(twin) < e)) continue;
            const auto& a = j["points"][j["triangles"][e / 3][e % 3].get<std::size_t>()];
            const auto& b = j["points"][j["triangles"][e / 3][(e % 3 + 1) % 3].get<std::size_t>()];
            count += a[0].get<double>() == x && b[0].get<double>() == x;
        }
        return count;
    };
    for (const auto& [keep, outline, middle] : std::vector<std::tuple<std::string, bool, bool>>{
             {"", false, false}, {"boundary", true, false}, {"all", true, true}}) {
        INFO("--keep-segments " << keep);
        std::vector<std::string> args = {"triangulate", dir.file("halves.poly"), "--format", "json", "--max-area", "0.1", "--min-angle", "20"};
        if (!keep.empty()) args.insert(args.end(), {"--keep-segments", keep});
        const nlohmann::json j = json_of(run_cli(dir, args));
        CHECK(checked_area(j) == 16);
        CHECK((pieces(j, 0) == 1) == outline);
        CHECK((pieces(j, 2) == 1) == middle);
    }
    const RunResult bad = run_cli(dir, {"triangulate", dir.file("halves.poly"), "--keep-segments", "inside"});
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("--keep-segments must be boundary or all") != std::string::npos);
}

TEST_CASE("hullkit triangulate: a .ele mesh refined (Triangle's -r), --triangle-areas (-ra), a .node alone", "[cli][constrained]") {
    TempDir dir("hullkit-triangulate");
    write_text(dir.file("rings.txt"), kSquareWithHole);
    REQUIRE(run_cli(dir, {"triangulate", dir.file("rings.txt"), "-o", dir.file("a.ele")}).exit_code == 0);
    // The 8 triangles of the annulus, refined: its hole stays, the bounds hold, the area is exact.
    const nlohmann::json fine = json_of(run_cli(dir, {"triangulate", dir.file("a.ele"), "--min-angle", "30", "--max-area", "0.1", "--format", "json"}));
    CHECK(checked_area(fine) == 12);
    for (std::size_t i = 0; i < 8; ++i) CHECK(fine["points"][i] == nlohmann::json::parse(std::vector<const char*>{"[0,0]", "[4,0]", "[4,4]", "[0,4]", "[1,1]", "[3,1]", "[3,3]", "[1,3]"}[i]));
    for (const auto& t : fine["triangles"]) {
        double cx = 0, cy = 0;
        for (const auto& i : t) cx += fine["points"][i.get<std::size_t>()][0].get<double>(), cy += fine["points"][i.get<std::size_t>()][1].get<double>();
        CHECK(!(cx / 3 > 1 && cx / 3 < 3 && cy / 3 > 1 && cy / 3 < 3));
    }
    CHECK(fine["triangles"].size() > 8 * 12);
    // Refined into .node/.ele again, then once more: the files chain as Triangle's do.
    REQUIRE(run_cli(dir, {"triangulate", dir.file("a.ele"), "--max-area", "0.5", "-o", dir.file("b.ele")}).exit_code == 0);
    CHECK(checked_area(json_of(run_cli(dir, {"triangulate", dir.file("b.ele"), "--format", "json", "--max-area", "0.2"}))) == 12);
    // Triangle 1 of the .ele gets a bound of its own; the others none (0 and -1).
    std::string area = "8\n1 0.01\n";
    for (int t = 2; t <= 8; ++t) area += std::to_string(t) + (t % 2 ? " 0\n" : " -1\n");
    write_text(dir.file("a.area"), area);
    const nlohmann::json own = json_of(run_cli(dir, {"triangulate", dir.file("a.ele"), "--triangle-areas", dir.file("a.area"), "--format", "json"}));
    CHECK(checked_area(own) == 12);
    std::istringstream ele(read_text(dir.file("a.ele")));
    std::size_t count, corners, attributes, index, a, b, c;
    ele >> count >> corners >> attributes >> index >> a >> b >> c;  // triangle 1, 1-based corners
    const auto xy = [&](std::size_t i) { return std::make_pair(own["points"][i][0].get<double>(), own["points"][i][1].get<double>()); };
    const auto in_first = [&](std::pair<double, double> p) {
        // Inside or on triangle 1 (a, b, c counter-clockwise), exactly.
        const std::size_t v[3] = {a - 1, b - 1, c - 1};
        for (int k = 0; k < 3; ++k) {
            const auto u = xy(v[k]), w = xy(v[(k + 1) % 3]);
            if ((mpq_class(w.first) - u.first) * (mpq_class(p.second) - u.second) - (mpq_class(w.second) - u.second) * (mpq_class(p.first) - u.first) < 0) return false;
        }
        return true;
    };
    std::size_t small = 0;
    double largest_elsewhere = 0;
    for (const auto& t : own["triangles"]) {
        const auto p = xy(t[0]), q = xy(t[1]), r = xy(t[2]);
        const double area = std::fabs((q.first - p.first) * (r.second - p.second) - (q.second - p.second) * (r.first - p.first)) / 2;
        if (!(in_first(p) && in_first(q) && in_first(r))) {
            largest_elsewhere = std::max(largest_elsewhere, area);
            continue;
        }
        ++small;
        CHECK(area <= 0.01);
    }
    CHECK(small >= 100);  // triangle 1 has area 1.5
    CHECK(largest_elsewhere > 0.2);  // the bound is triangle 1's alone
    // A .node alone: the Delaunay triangulation of its vertices, the whole hull.
    CHECK(checked_area(json_of(run_cli(dir, {"triangulate", dir.file("a.node"), "--format", "json"}))) == 16);
    // Errors name the file and line, and the triangles and vertices as the files number them.
    write_text(dir.file("bad.node"), read_text(dir.file("a.node")));
    write_text(dir.file("bad.ele"), "2 3 0\n1 1 2 9\n2 1 3 4\n");
    const RunResult range = run_cli(dir, {"triangulate", dir.file("bad.ele")});
    CHECK(range.exit_code == 2);
    CHECK(range.err.find("bad.ele line 2: corner 9 is not one of the 8 vertices (numbered from 1)") != std::string::npos);
    write_text(dir.file("bad.ele"), "2 3 0\n1 1 2 6\n2 6 2 1\n");
    const RunResult overlap = run_cli(dir, {"triangulate", dir.file("bad.ele")});
    CHECK(overlap.exit_code == 2);
    CHECK(overlap.err.find("bad.ele line 3: triangles 1 and 2 overlap: both have the edge from point ") != std::string::npos);
    CHECK(overlap.err.find("point 0") == std::string::npos);  // the .node's numbers (from 1)
    write_text(dir.file("bad.ele"), "1 3 0\n1 1 5 7\n");  // (0,0), (1,1), (3,3): collinear
    CHECK(run_cli(dir, {"triangulate", dir.file("bad.ele")}).err.find("bad.ele line 2: triangle 1 (points 1, 5, 7) has no area") != std::string::npos);
    // Numbered from 0 in the files, and triangles numbered on their own: the same numbers back.
    write_text(dir.file("zero.node"), "3 2 0 0\n0 0 0\n1 1 1\n2 3 3\n");
    write_text(dir.file("zero.ele"), "1 3 0\n7 0 1 2\n");
    CHECK(run_cli(dir, {"triangulate", dir.file("zero.ele")}).err.find("zero.ele line 2: triangle 7 (points 0, 1, 2) has no area") != std::string::npos);
    write_text(dir.file("short.area"), "2\n1 0.5\n2 0.5\n");
    CHECK(run_cli(dir, {"triangulate", dir.file("a.ele"), "--triangle-areas", dir.file("short.area")}).err.find("2 areas for a mesh of 8 triangles") != std::string::npos);
    CHECK(run_cli(dir, {"triangulate", dir.file("rings.txt"), "--triangle-areas", dir.file("a.area")}).err.find("the input must be a Triangle .ele file") != std::string::npos);
    CHECK(run_cli(dir, {"triangulate", dir.file("a.ele"), "--convex"}).err.find("--convex applies to .poly input") != std::string::npos);
    write_text(dir.file("lonely.ele"), "1 3 0\n1 1 2 3\n");
    CHECK(run_cli(dir, {"triangulate", dir.file("lonely.ele")}).err.find("lonely.node") != std::string::npos);
}
