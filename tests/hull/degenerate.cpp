// Degenerate inputs: the corpus in tests/data/degenerate (see its README.md) and seeded random small
// inputs full of coplanar, collinear and repeated points. Every hull is checked by hullkit::verify
// and, independently, with GMP (hull_checks.hpp and the checks below); quickhull and gift wrapping
// must agree on the dimension, the vertices and the merged faces.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hull_checks.hpp"
#include "hullkit/hull.hpp"
#include "hullkit/mesh_io.hpp"
#include "hullkit/verify.hpp"

using hullkit::Algorithm;
using hullkit::Hull;

namespace {

namespace fs = std::filesystem;

using Faces = std::vector<std::vector<std::uint32_t>>;

std::string describe(const hullkit::VerifyReport& report) {
    std::ostringstream out;
    for (const auto& line : report.lines()) out << "  " << line << "\n";
    for (const auto& note : report.notes) out << "  note: " << note << "\n";
    return out.str();
}

std::string list(const std::vector<std::uint32_t>& indices) {
    std::ostringstream out;
    for (std::uint32_t i : indices) out << i << " ";
    return out.str();
}

/// Independent exact checks of a result of dimension < 3 (GMP via hull_checks.hpp): the
/// dimension is right and the listed vertices are corners that enclose all points.
std::vector<std::string> low_dimension_problems(const std::vector<double>& xyz, const Hull& hull) {
    std::vector<std::string> problems;
    const std::size_t n = xyz.size() / 3;
    auto at = [&](std::uint32_t i) { return &xyz[3 * i]; };
    const auto& v = hull.vertices;
    switch (hull.dimension) {
        case -1:
            if (n != 0 || !v.empty()) problems.push_back("empty hull of a non-empty set");
            break;
        case 0:
            if (v.size() != 1) return {"a point needs one vertex"};
            for (std::size_t i = 0; i < n; ++i) {
                if (!std::equal(at(v[0]), at(v[0]) + 3, at(static_cast<std::uint32_t>(i))))
                    problems.push_back("point " + std::to_string(i) + " differs");
            }
            break;
        case 1: {
            if (v.size() != 2) return {"a segment needs two vertices"};
            for (std::size_t i = 0; i < n; ++i) {
                const double* p = at(static_cast<std::uint32_t>(i));
                if (!hullkit_test::exact_collinear(at(v[0]), at(v[1]), p))
                    problems.push_back("point " + std::to_string(i) + " is off the line");
                for (int axis = 0; axis < 3; ++axis) {
                    if (p[axis] < std::min(at(v[0])[axis], at(v[1])[axis]) || p[axis] > std::max(at(v[0])[axis], at(v[1])[axis]))
                        problems.push_back("point " + std::to_string(i) + " is beyond the ends");
                }
            }
            break;
        }
        case 2: {
            if (v.size() < 3) return {"a polygon needs three vertices"};
            if (hullkit_test::exact_collinear(at(v[0]), at(v[1]), at(v[2]))) return {"first three vertices collinear"};
            // A point off the polygon's plane: the points have volume.
            for (std::size_t i = 0; i < n; ++i) {
                if (hullkit_test::exact_orient3d(at(v[0]), at(v[1]), at(v[2]), at(static_cast<std::uint32_t>(i))) != 0)
                    problems.push_back("point " + std::to_string(i) + " is off the plane");
            }
            // Lift the polygon's edges to planes through an apex off the plane: every point must be on
            // the inner side of every edge, and every corner strictly inside the others' edges.
            double apex[3] = {at(v[0])[0] + hull.normal[0], at(v[0])[1] + hull.normal[1], at(v[0])[2] + hull.normal[2]};
            const int up = hullkit_test::exact_orient3d(at(v[0]), at(v[1]), at(v[2]), apex);
            if (up == 0) return {"the rounded normal lies in the plane"};
            if (up < 0) problems.push_back("the polygon is clockwise seen from where Hull::normal points");
            const std::size_t m = v.size();
            for (std::size_t k = 0; k < m; ++k) {
                const double* a = at(v[k]);
                const double* b = at(v[(k + 1) % m]);
                for (std::size_t i = 0; i < n; ++i) {
                    const int side = hullkit_test::exact_orient3d(a, b, apex, at(static_cast<std::uint32_t>(i)));
                    const bool corner = std::find(v.begin(), v.end(), i) != v.end() && i != v[k] && i != v[(k + 1) % m];
                    // det[b-a, apex-a, q-a] is -sign(up) for q strictly inside edge a-b (apex - a is
                    // the normal plus a vector in the plane, which adds nothing).
                    if (side * up > 0 || (corner && side == 0))
                        problems.push_back("point " + std::to_string(i) + " is not inside edge " + std::to_string(k));
                }
            }
            break;
        }
        default:
            problems.push_back("unexpected dimension " + std::to_string(hull.dimension));
    }
    return problems;
}

/// True when every |coordinate| is so small that the hull's volume is below the smallest double.
bool tiny_volume(const std::vector<double>& xyz) {
    double largest = 0.0;
    for (double c : xyz) largest = std::max(largest, std::fabs(c));
    return largest < 1e-110;  // volume < (2e-110)^3 = 8e-330
}

/// The merged faces as sets compared in a fixed order (each face already starts at its lowest index).
Faces canonical_faces(const Hull& hull) {
    Faces faces;
    for (std::size_t f = 0; f + 1 < hull.face_offsets.size(); ++f) {
        faces.emplace_back(hull.face_vertices.begin() + hull.face_offsets[f],
                           hull.face_vertices.begin() + hull.face_offsets[f + 1]);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

/// Computes the hull with both algorithms, merge on and off, and checks everything. Returns the
/// dimension found.
int check_all_ways(const std::vector<double>& xyz, const std::string& name, bool gmp = true) {
    Hull reference;
    Faces reference_faces;
    bool first = true;
    for (bool merge : {false, true}) {
        for (Algorithm algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
            INFO(name << ": " << hullkit::algorithm_name(algorithm) << (merge ? ", merged" : ""));
            hullkit::HullOptions options;
            options.algorithm = algorithm;
            options.merge_coplanar = merge;
            const Hull hull = hullkit::hull(xyz, options);
            INFO(hull.error);
            REQUIRE(hull.ok());

            const hullkit::VerifyReport report = hullkit::verify(xyz, hull);
            INFO("verify:\n" << describe(report));
            CHECK(report.ok);
            if (gmp) {
                auto problems = hull.dimension == 3 ? hullkit_test::hull_problems(xyz, hull)
                                                    : low_dimension_problems(xyz, hull);
                // hull_problems wants Hull::volume > 0, but a volume below the smallest double
                // (about 5e-324: coordinates near 1e-150 give 1e-450) rounds to 0; verify() has
                // shown the volume positive exactly.
                if (hull.volume == 0.0 && tiny_volume(xyz)) {
                    problems.erase(std::remove_if(problems.begin(), problems.end(),
                                                  [](const std::string& p) { return p.rfind("volume ", 0) == 0; }),
                                   problems.end());
                }
                INFO("GMP checks:\n" << hullkit_test::join(problems));
                CHECK(problems.empty());
            }
            if (first) {
                reference = hull;
                first = false;
            } else {
                INFO("vertices " << list(hull.vertices) << "\nversus   " << list(reference.vertices));
                CHECK(hull.dimension == reference.dimension);
                CHECK(hull.vertices == reference.vertices);
            }
            if (merge && hull.dimension >= 2) {
                const Faces faces = canonical_faces(hull);
                CHECK(faces.size() == (hull.dimension == 2 ? 1u : report.face_count));
                if (algorithm == Algorithm::Quickhull) {
                    reference_faces = faces;
                } else {
                    CHECK(faces == reference_faces);
                }
            }
        }
    }
    return reference.dimension;
}

int expected_dimension(const std::string& text) {
    const std::string tag = "# dimension: ";
    const std::size_t at = text.find(tag);
    REQUIRE(at != std::string::npos);
    return std::stoi(text.substr(at + tag.size()));
}

}  // namespace

TEST_CASE("degenerate: every corpus file, both algorithms, merge on and off") {
    const std::vector<fs::path> files = hullkit_test::degenerate_corpus();
    REQUIRE(files.size() >= 40);
    int by_dimension[5] = {0, 0, 0, 0, 0};
    for (const fs::path& file : files) {
        std::string text, error;
        REQUIRE(hullkit::read_file(file.string(), &text, &error));
        const hullkit::PointsResult points = hullkit::parse_points(text, file.string());
        INFO(points.error);
        REQUIRE(points.ok());
        const int expected = expected_dimension(text);
        const int dimension = check_all_ways(points.xyz, file.filename().string());
        INFO(file.filename().string());
        CHECK(dimension == expected);
        ++by_dimension[dimension + 1];
    }
    // The corpus covers every dimension a non-empty input can have.
    CHECK(by_dimension[1] > 0);
    CHECK(by_dimension[2] > 0);
    CHECK(by_dimension[3] > 0);
    CHECK(by_dimension[4] > 0);
}

TEST_CASE("degenerate: corpus files keep what they are named after") {
    auto load = [](const std::string& name) {
        std::string text, error;
        REQUIRE(hullkit::read_file(std::string(HULLKIT_TEST_DATA) + "/degenerate/" + name, &text, &error));
        return hullkit::parse_points(text, name).xyz;
    };
    hullkit::HullOptions merged;
    merged.merge_coplanar = true;

    const Hull grid = hullkit::hull(load("grid-5x5x5.txt"), merged);
    CHECK(grid.vertices.size() == 8);
    CHECK(grid.face_offsets.size() == 7);  // 6 squares
    const Hull rotated = hullkit::hull(load("grid-5x5x5-pythagorean-rotation.txt"), merged);
    CHECK(rotated.vertices.size() == 8);
    CHECK(rotated.face_offsets.size() == 7);
    const Hull box = hullkit::hull(load("threejs-issue-30407-box-geometry-vertices.txt"), merged);
    CHECK(box.vertices.size() == 8);
    CHECK(box.face_offsets.size() == 7);
    const Hull prism = hullkit::hull(load("karimnaaji-3d-quickhull-issue-2-octagonal-prism.txt"), merged);
    CHECK(prism.vertices.size() == 16);
    CHECK(prism.face_offsets.size() == 11);  // 2 octagons and 8 rectangles
    const auto sphere = load("cospherical-integer-r2-25.txt");
    CHECK(hullkit::hull(sphere).vertices.size() == sphere.size() / 3);  // every point is extreme
    const Hull pentagon = hullkit::hull(load("quickhull3d-issue-30-five-points.txt"));
    CHECK(pentagon.dimension == 2);
    CHECK(pentagon.vertices.size() == 5);
    const Hull repeated = hullkit::hull(load("duplicated-10x.txt"));
    for (std::uint32_t v : repeated.vertices) CHECK(v % 10 == 0);  // the first copy of each point
}

TEST_CASE("degenerate: thousands of small random degenerate inputs agree and verify") {
    std::mt19937_64 rng(20240611);
    int by_dimension[5] = {0, 0, 0, 0, 0};
    for (int round = 0; round < 3000; ++round) {
        int kind = 0;
        const std::vector<double> xyz = hullkit_test::random_degenerate(rng, &kind);
        std::ostringstream name;
        name << "round " << round << " kind " << kind << ":";
        for (double c : xyz) name << " " << c;
        const int dimension = check_all_ways(xyz, name.str());
        ++by_dimension[dimension + 1];
    }
    INFO("dimensions 0..3: " << by_dimension[1] << " " << by_dimension[2] << " " << by_dimension[3] << " "
                             << by_dimension[4]);
    CHECK(by_dimension[2] > 100);  // collinear draws
    CHECK(by_dimension[3] > 100);  // coplanar draws
    CHECK(by_dimension[4] > 1000);
}

TEST_CASE("degenerate: a sliver tetrahedron does not get a negative volume") {
    // k * 0.1 for small k: coplanar as decimals, not as doubles (3 * 0.1 = 0.30000000000000004).
    // The exact volume of the tetrahedron is +9.2518585385429770e-20; the triangles are right.
    const std::vector<double> xyz = {0.1, 0.30000000000000004, 0.1, 0.30000000000000004, 0.2, 0.30000000000000004,
                                     0.0, 0.30000000000000004, 0.30000000000000004, 0.4, 0.2, 0.1};
    for (Algorithm algorithm : {Algorithm::Quickhull, Algorithm::Giftwrap}) {
        INFO(hullkit::algorithm_name(algorithm));
        hullkit::HullOptions options;
        options.algorithm = algorithm;
        const Hull hull = hullkit::hull(xyz, options);
        REQUIRE(hull.ok());
        REQUIRE(hull.dimension == 3);
        const auto report = hullkit::verify(hullkit::PointSpan(xyz), hull.triangles.data(), hull.face_count());
        INFO(describe(report));
        CHECK(report.ok);
        CHECK(hull.volume >= 0.0);  // hullkit::hull reports -1.4456028966473392e-19
    }
}
