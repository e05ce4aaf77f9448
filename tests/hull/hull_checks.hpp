// Independent checks of a hull for the tests: exact rational arithmetic (GMP), nothing shared
// with the library's own side tests.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "hullkit/hull.hpp"

namespace hullkit_test {

/// Whether two doubles have the same bits (the results promise bits, not just values).
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Exact sign of ((b-a) x (c-a)) . (d-a) by GMP rational arithmetic.
inline int rational_orient3d(const double* a, const double* b, const double* c, const double* d) {
    auto q = [](double v) { return mpq_class(v); };
    const mpq_class ebx = q(b[0]) - q(a[0]), eby = q(b[1]) - q(a[1]), ebz = q(b[2]) - q(a[2]);
    const mpq_class ecx = q(c[0]) - q(a[0]), ecy = q(c[1]) - q(a[1]), ecz = q(c[2]) - q(a[2]);
    const mpq_class edx = q(d[0]) - q(a[0]), edy = q(d[1]) - q(a[1]), edz = q(d[2]) - q(a[2]);
    const mpq_class exact =
        edx * (eby * ecz - ebz * ecy) + edy * (ebz * ecx - ebx * ecz) + edz * (ebx * ecy - eby * ecx);
    return sgn(exact);
}

/// Exact sign of ((b-a) x (c-a)) . (d-a): a double filter with a generous bound (after scaling the
/// four points by one power of two so that the largest coordinate is near 1, which changes no
/// sign), then GMP.
inline int exact_orient3d(const double* a, const double* b, const double* c, const double* d) {
    const double* in[4] = {a, b, c, d};
    double largest = 0.0;
    for (const double* p : in)
        for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(p[k]));
    int exponent = 0;  // unit-scale data (the common case) is left alone
    if (largest < 0x1p-100 || largest > 0x1p+100) std::frexp(largest, &exponent);
    double s[4][3];
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) {
            s[i][k] = exponent == 0 ? in[i][k] : std::ldexp(in[i][k], -exponent);
            // A coordinate that would lose bits to underflow: no shortcut.
            if (in[i][k] != 0.0 && std::fabs(s[i][k]) < 1e-250) return rational_orient3d(a, b, c, d);
        }
    }
    const double bx = s[1][0] - s[0][0], by = s[1][1] - s[0][1], bz = s[1][2] - s[0][2];
    const double cx = s[2][0] - s[0][0], cy = s[2][1] - s[0][1], cz = s[2][2] - s[0][2];
    const double dx = s[3][0] - s[0][0], dy = s[3][1] - s[0][1], dz = s[3][2] - s[0][2];
    const double det = dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx);
    const double permanent = std::fabs(dx) * (std::fabs(by * cz) + std::fabs(bz * cy)) +
                             std::fabs(dy) * (std::fabs(bz * cx) + std::fabs(bx * cz)) +
                             std::fabs(dz) * (std::fabs(bx * cy) + std::fabs(by * cx));
    // Far above the rounding error of this expression (about 1e-15 * permanent, differences
    // included), trusted only far from underflow.
    if (permanent > 1e-200 && std::fabs(det) > 1e-10 * permanent) return det > 0 ? 1 : -1;
    return rational_orient3d(a, b, c, d);
}

/// Exact test that c lies on the line through a and b.
inline bool exact_collinear(const double* a, const double* b, const double* c) {
    auto q = [](double v) { return mpq_class(v); };
    const mpq_class ex = q(b[0]) - q(a[0]), ey = q(b[1]) - q(a[1]), ez = q(b[2]) - q(a[2]);
    const mpq_class fx = q(c[0]) - q(a[0]), fy = q(c[1]) - q(a[1]), fz = q(c[2]) - q(a[2]);
    return ey * fz - ez * fy == 0 && ez * fx - ex * fz == 0 && ex * fy - ey * fx == 0;
}

/// Everything wrong with `hull` as the convex hull of `points`; empty when it is right:
/// - indices in range, no zero-area triangle;
/// - a closed two-manifold: every directed edge once and its reverse once, V - E + F = 2;
/// - every input point on or below every face plane (exact), and the hull has volume.
inline std::vector<std::string> hull_problems(const std::vector<double>& points, const hullkit::Hull& hull) {
    std::vector<std::string> problems;
    auto fail = [&](const std::string& what) {
        if (problems.size() < 20) problems.push_back(what);
    };
    const std::size_t n = points.size() / 3;
    const auto& t = hull.triangles;
    if (!hull.ok()) return {"hull failed: " + hull.error};
    if (t.empty() || t.size() % 3 != 0) return {"triangle array size " + std::to_string(t.size())};
    for (std::uint32_t i : t)
        if (i >= n) return {"index " + std::to_string(i) + " out of range"};
    auto at = [&](std::uint32_t i) { return &points[3 * i]; };

    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t f = 0; f < t.size(); f += 3) {
        if (exact_collinear(at(t[f]), at(t[f + 1]), at(t[f + 2])))
            fail("triangle " + std::to_string(f / 3) + " has zero area");
        for (int k = 0; k < 3; ++k) ++directed[{t[f + k], t[f + (k + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1)
            fail("edge " + std::to_string(edge.first) + "->" + std::to_string(edge.second) +
                 " is not used once each way");
    }
    std::set<std::uint32_t> used(t.begin(), t.end());
    const long long v = static_cast<long long>(used.size());
    const long long f = static_cast<long long>(t.size() / 3);
    const long long e = static_cast<long long>(directed.size() / 2);
    if (v - e + f != 2) fail("Euler characteristic " + std::to_string(v - e + f));
    if (std::vector<std::uint32_t>(used.begin(), used.end()) != hull.vertices) fail("vertices differ from the triangles' corners");

    for (std::size_t face = 0; face < t.size(); face += 3) {
        for (std::uint32_t p = 0; p < n; ++p) {
            if (exact_orient3d(at(t[face]), at(t[face + 1]), at(t[face + 2]), at(p)) > 0) {
                fail("point " + std::to_string(p) + " is above face " + std::to_string(face / 3));
                break;
            }
        }
    }
    if (!(hull.volume > 0)) fail("volume " + std::to_string(hull.volume));
    return problems;
}

inline std::string join(const std::vector<std::string>& lines) {
    std::ostringstream out;
    for (const auto& line : lines) out << line << "\n";
    return out.str();
}

/// The 8 corners of the cube [-half, half]^3; corner i has x > 0 if bit 0 of i is set, y > 0 if
/// bit 1, z > 0 if bit 2.
inline std::vector<double> cube_corners(double half = 1.0) {
    std::vector<double> xyz;
    for (int i = 0; i < 8; ++i) {
        xyz.push_back(i & 1 ? half : -half);
        xyz.push_back(i & 2 ? half : -half);
        xyz.push_back(i & 4 ? half : -half);
    }
    return xyz;
}

/// The integer grid [-half, half)^2 lifted to z = x^2 + y^2: every point extreme, square faces
/// (each two exactly coplanar triangles), row by row.
inline std::vector<double> lifted_grid(int half) {
    std::vector<double> xyz;
    for (int x = -half; x < half; ++x) {
        for (int y = -half; y < half; ++y) xyz.insert(xyz.end(), {double(x), double(y), double(x * x + y * y)});
    }
    return xyz;
}

/// The integer points on the six faces of [0, side]^3: large coplanar faces, and the points on
/// the cube's edges and corners repeated (two or three times).
inline std::vector<double> box_surface(int side) {
    std::vector<double> xyz;
    for (int a = 0; a <= side; ++a) {
        for (int b = 0; b <= side; ++b) {
            for (double fixed : {0.0, double(side)}) {
                xyz.insert(xyz.end(), {fixed, double(a), double(b)});
                xyz.insert(xyz.end(), {double(a), fixed, double(b)});
                xyz.insert(xyz.end(), {double(a), double(b), fixed});
            }
        }
    }
    return xyz;
}

/// Seeded point clouds shared by the tests and benchmarks.
enum class Cloud { Cube, Ball, Sphere };

inline std::vector<double> random_cloud(Cloud kind, std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::normal_distribution<double> gauss;
    std::vector<double> xyz;
    xyz.reserve(3 * n);
    while (xyz.size() < 3 * n) {
        double p[3];
        if (kind == Cloud::Sphere) {
            for (double& c : p) c = gauss(rng);
            const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            if (r == 0) continue;
            for (double& c : p) c /= r;
        } else {
            for (double& c : p) c = unit(rng);
            if (kind == Cloud::Ball && p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 1.0) continue;
        }
        xyz.insert(xyz.end(), p, p + 3);
    }
    return xyz;
}


/// The files of the degenerate corpus, tests/data/degenerate/*.txt, sorted.
inline std::vector<std::filesystem::path> degenerate_corpus() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(HULLKIT_TEST_DATA) / "degenerate")) {
        if (entry.path().extension() == ".txt") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// Small random inputs where degeneracies are the rule: points from tiny integer grids (many
/// coplanar, collinear and repeated points), all-coplanar and all-collinear draws on tilted
/// integer lattices, a plane plus a few points off it, and rounded (inexact) versions.
inline std::vector<double> random_degenerate(std::mt19937_64& rng, int* kind_out) {
    std::uniform_int_distribution<int> count_of(4, 30);
    const int count = count_of(rng);
    const int kind = std::uniform_int_distribution<int>(0, 6)(rng);
    *kind_out = kind;
    auto integer = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    auto vector_of = [&](int range) {
        return std::vector<int>{integer(-range, range), integer(-range, range), integer(-range, range)};
    };
    std::vector<double> xyz;
    const int side = integer(1, 3);
    const auto base = vector_of(5), u = vector_of(3), v = vector_of(3), w = vector_of(3);
    for (int i = 0; i < count; ++i) {
        double p[3];
        switch (kind) {
            case 0:  // a tiny grid: side + 1 values per axis
            case 1:
                for (double& c : p) c = integer(0, side);
                break;
            case 2: {  // all coplanar (or less, when u and v happen to be parallel)
                const int a = integer(-3, 3), b = integer(-3, 3);
                for (int k = 0; k < 3; ++k) p[k] = base[k] + a * u[k] + b * v[k];
                break;
            }
            case 3: {  // all collinear
                const int a = integer(-6, 6);
                for (int k = 0; k < 3; ++k) p[k] = base[k] + a * u[k];
                break;
            }
            case 4: {  // a plane and a few points off it
                const int a = integer(-3, 3), b = integer(-3, 3), c = i % 7 == 6 ? integer(-1, 1) : 0;
                for (int k = 0; k < 3; ++k) p[k] = base[k] + a * u[k] + b * v[k] + c * w[k];
                break;
            }
            case 5: {  // a tiny grid scaled by 0.1 (rounded: nearly, not exactly, degenerate)
                for (double& c : p) c = integer(0, side) * 0.1;
                break;
            }
            default: {  // a repeated handful of points
                if (i < 4 || integer(0, 2) == 0) {
                    for (double& c : p) c = integer(-2, 2);
                } else {
                    const std::size_t j = static_cast<std::size_t>(integer(0, static_cast<int>(xyz.size() / 3) - 1));
                    std::copy(&xyz[3 * j], &xyz[3 * j] + 3, p);
                }
            }
        }
        xyz.insert(xyz.end(), p, p + 3);
    }
    return xyz;
}


}  // namespace hullkit_test
