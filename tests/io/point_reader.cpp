// Tests of hullkit::PointReader (point_reader.hpp): whatever the batch size, the thread count and
// the kind of input (text in memory, a regular file, a stream of unknown size), it hands out
// exactly the points (bitwise) and the error message of read_points / parse_points on the same
// bytes, and the batches before an error are points that stand.
#include "hullkit/point_reader.hpp"

#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

#include "cli/cli_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using hullkit::PointReader;
using hullkit::PointReaderOptions;
using hullkit::PointsResult;
using hullkit_test::data_path;

namespace {

/// How the bytes reach the reader.
enum class Via { Memory, File, Stream };

const char* via_name(Via via) {
    switch (via) {
        case Via::Memory: return "memory";
        case Via::File: return "file";
        case Via::Stream: return "stream";
    }
    return "?";
}

/// Everything a reader hands out, and its error.
struct Outcome {
    std::vector<double> xyz;
    std::string error;
    std::vector<std::string> warnings;
};

/// Reads every batch, checking the batch contract on the way: at least one whole point per batch,
/// the counters in step, an empty array and a one-line message at the end.
Outcome read_all(PointReader& reader, std::uint64_t size) {
    Outcome out;
    std::vector<double> batch = {42.0};  // replaced by the first batch
    std::uint64_t bytes = 0;
    while (reader.next(&batch)) {
        REQUIRE_FALSE(batch.empty());
        REQUIRE(batch.size() % 3 == 0);
        out.xyz.insert(out.xyz.end(), batch.begin(), batch.end());
        REQUIRE(reader.points_read() == out.xyz.size() / 3);
        REQUIRE(reader.bytes_read() >= bytes);
        bytes = reader.bytes_read();
    }
    CHECK(batch.empty());
    CHECK(reader.points_read() == out.xyz.size() / 3);
    CHECK(reader.bytes_read() <= size);
    CHECK_FALSE(reader.next(&batch));  // the end stays the end
    out.error = reader.error();
    out.warnings = reader.warnings();
    CHECK(out.error.find('\n') == std::string::npos);
    return out;
}

Outcome read_via(const std::string& bytes, const std::string& source, Via via, const PointReaderOptions& options) {
    if (via == Via::Memory) {
        PointReader reader(std::string_view(bytes), source, options);
        CHECK(reader.size() == bytes.size());
        return read_all(reader, bytes.size());
    }
    // fmemopen has no file descriptor, so its size is unknown, as for a pipe. (It refuses 0 bytes.)
    std::FILE* file = via == Via::Stream && !bytes.empty()
                          ? fmemopen(const_cast<char*>(bytes.data()), bytes.size(), "rb")
                          : std::tmpfile();
    REQUIRE(file != nullptr);
    if (via == Via::File || bytes.empty()) {
        REQUIRE(std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size());
        std::rewind(file);
    }
    Outcome out;
    {
        PointReader reader(file, source, options);
        if (via == Via::File) CHECK(reader.size() == bytes.size());
        out = read_all(reader, bytes.size());
    }
    std::fclose(file);
    return out;
}

/// Bitwise equality (NaN payloads and -0 included).
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

/// Whether `part` is the start of `whole`, bitwise.
bool is_prefix(const std::vector<double>& part, const std::vector<double>& whole) {
    return part.size() <= whole.size() &&
           (part.empty() || std::memcmp(part.data(), whole.data(), part.size() * sizeof(double)) == 0);
}

const std::size_t kBatches[] = {64, 1000, std::size_t{1} << 20};
const unsigned kThreads[] = {1, 2, 3, 8};

/// Reads `bytes` with every batch size, thread count and kind of input and checks that the result
/// is read_points' (or with `text_only`, parse_points') on the same bytes: the same points bitwise,
/// or the same message. On an error the points handed out before it must be the first points of
/// `before_error` (the points before the bad line), when the caller knows them.
void check_agrees(const std::string& bytes, const std::string& source, bool text_only,
                  const std::vector<double>* before_error = nullptr,
                  std::initializer_list<Via> vias = {Via::Memory, Via::File, Via::Stream},
                  const std::vector<std::size_t>& batches = {std::begin(kBatches), std::end(kBatches)}) {
    const PointsResult expected = text_only ? hullkit::parse_points(bytes, source, 1) : hullkit::read_points(bytes, source);
    for (std::size_t batch : batches) {
        for (unsigned threads : kThreads) {
            for (Via via : vias) {
                PointReaderOptions options;
                options.batch_bytes = batch;
                options.threads = threads;
                options.text_only = text_only;
                INFO(source << (text_only ? " text-only" : "") << ", batch " << batch << ", " << threads << " threads, via "
                            << via_name(via));
                const Outcome got = read_via(bytes, source, via, options);
                std::string expected_error = expected.error;
                // A stream has no known size, and a binary STL is recognised by its size: parse_points
                // then sees binary data (read_points reads such a stream whole and knows).
                const std::string stl = "not a point file: binary STL is not supported";
                if (via == Via::Stream && text_only && expected_error.find(stl) != std::string::npos) {
                    CHECK(got.error.rfind(source + ": not a point file: binary data (byte 0x", 0) == 0);
                } else {
                    CHECK(got.error == expected_error);
                }
                if (expected.ok()) {
                    CHECK(same_bits(got.xyz, expected.xyz));
                    CHECK(got.warnings == expected.warnings);  // whatever the pieces, the same tally
                } else if (before_error) {
                    CHECK(is_prefix(got.xyz, *before_error));
                }
            }
        }
    }
}

/// The points of `count` lines of random coordinates (numbers of every length and exponent), and
/// their text: separated by spaces, tabs or a comma, CRLF on some lines, with blank lines and
/// comments in between.
struct PointLines {
    std::vector<double> xyz;
    std::string text;
};

PointLines random_lines(std::size_t count, std::uint64_t seed, bool plain = false) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    PointLines lines;
    for (std::size_t i = 0; i < count; ++i) {
        if (!plain && random() % 9 == 0) lines.text += random() % 2 ? "\n" : "# a comment, 1 2 3\n";
        for (int k = 0; k < 3; ++k) {
            const double value = uniform(random) * std::pow(10.0, static_cast<int>(random() % 40) - 20);
            lines.xyz.push_back(value);
            lines.text += hullkit::format_double(value);
            if (k < 2) lines.text += plain ? " " : random() % 3 == 0 ? "\t" : random() % 3 == 0 ? ", " : " ";
        }
        lines.text += !plain && random() % 5 == 0 ? " # trailing\r\n" : "\n";
    }
    return lines;
}

/// `lines` without comments and commas, as rbox and OFF bodies want them.
PointLines plain_lines(std::size_t count, std::uint64_t seed) { return random_lines(count, seed, true); }

}  // namespace

// ---- text ----

TEST_CASE("point_reader: every file in tests/data reads as read_points and parse_points read it", "[threads]") {
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(HULLKIT_TEST_DATA)) {
        if (!entry.is_regular_file()) continue;
        const std::string bytes = hullkit_test::read_text(entry.path().string());
        const std::string name = entry.path().filename().string();
        check_agrees(bytes, name, false, nullptr, {Via::Memory, Via::Stream});
        check_agrees(bytes, name, true, nullptr, {Via::Memory, Via::Stream});
        ++files;
    }
    CHECK(files > 50);
    // A regular file too, for a few of them (its size decides binary STL).
    for (const char* name : {"malformed-line3.txt", "tetra.off", "cube.obj", "binary-two-triangles.stl", "route/plate.ply",
                             "route/load.stl"}) {
        const std::string bytes = hullkit_test::read_text(data_path(name));
        check_agrees(bytes, name, false, nullptr, {Via::File});
        check_agrees(bytes, name, true, nullptr, {Via::File});
    }
}

TEST_CASE("point_reader: xyz with comments, commas, blank lines, CRLF, no final newline", "[threads]") {
    const PointLines lines = random_lines(400, 1);
    REQUIRE(hullkit::parse_points(lines.text, "t.txt", 1).xyz == lines.xyz);  // the generator is right
    check_agrees(lines.text, "t.txt", true);
    check_agrees(lines.text, "t.txt", false, nullptr, {Via::Stream});
    check_agrees(lines.text.substr(0, lines.text.size() - 1), "t.txt", true);  // no final newline
    for (const char* text : {"# only\n\n# comments\n", "", "\n\n\n", "1 2 3", "1 2 3\r\n4 5 6\r\n",
                             "1,2,3\n4 , 5 ,6\n7,,8,9\n"}) {
        check_agrees(text, "t.txt", true);
    }
}

TEST_CASE("point_reader: lines longer than a batch", "[threads]") {
    const PointLines lines = random_lines(200, 2);
    const std::string comment = "# " + std::string(5000, 'c') + "\n";
    const std::string number = "1" + std::string(3000, '0') + " -0 0\n";  // 1e3000: inf, as strtod has it
    check_agrees(comment + lines.text + comment + number + lines.text, "t.txt", true);
    check_agrees("3 rbox\n" + std::to_string(402) + "\n" + comment + lines.text + number + lines.text + comment,
                 "t.txt", true);
    check_agrees(number + number, "t.txt", true);
}

TEST_CASE("point_reader: headers after more than the first read", "[threads]") {
    // The format is decided on the first 64 KiB; a header further down is read on.
    std::string comments;
    while (comments.size() < 70000) comments += "# " + std::string(77, 'c') + "\n";
    const PointLines lines = plain_lines(100, 16);
    check_agrees(comments + "3 rbox\n100\n" + lines.text, "r.txt", true, nullptr, {Via::File, Via::Stream}, {1000});
    check_agrees(comments + "OFF\n\n" + comments + "100 0 0\n" + lines.text, "m.off", true, nullptr, {Via::Stream}, {1000});
    check_agrees(comments + "3 rbox\n" + comments, "r.txt", true, nullptr, {Via::Stream}, {1000});
    check_agrees(comments, "e.txt", true, nullptr, {Via::Stream}, {1000});
}

TEST_CASE("point_reader: a bad number in the 3rd of 5 batches names its line", "[threads]") {
    for (std::size_t batch : kBatches) {
        INFO("batch " << batch);
        // Five batches of lines, the bad one where the third batch starts.
        PointLines lines = random_lines(1, 3);
        std::uint64_t seed = 4;
        while (lines.text.size() < 5 * batch) {
            const PointLines more = random_lines(64, ++seed);
            lines.text += more.text;
            lines.xyz.insert(lines.xyz.end(), more.xyz.begin(), more.xyz.end());
        }
        // Cut at the line end after 2.5 batches and put the bad line there.
        const std::size_t cut = lines.text.find('\n', 5 * batch / 2) + 1;
        const std::string before = lines.text.substr(0, cut);
        const std::vector<double> before_points = hullkit::parse_points(before, "t.txt", 1).xyz;
        const std::size_t line = static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n')) + 1;
        const std::string point = std::to_string(before_points.size() / 3);
        // A bad number, and non-finite ones, which name their point too: counted across batches.
        const std::pair<std::string, std::string> bad[] = {
            {"1 2e 3", "coordinate \"2e\" is not a number"},
            {"1 nan 3", "coordinate \"nan\" of point " + point + " is not a finite number"},
            {"1, 2, 1e400", "coordinate \"1e400\" of point " + point + " is out of the double range"}};
        for (const auto& [bad_line, message] : bad) {
            const std::string text = before + bad_line + "\n" + lines.text.substr(cut);
            CHECK(hullkit::parse_points(text, "t.txt", 1).error == "t.txt:" + std::to_string(line) + ": " + message);
            check_agrees(text, "t.txt", true, &before_points, {Via::Memory, Via::File, Via::Stream}, {batch});
        }
    }
}

TEST_CASE("point_reader: a byte-order mark and a CSV header row, whatever the batches", "[threads]") {
    const PointLines lines = random_lines(300, 31);
    for (const std::string start : {"\xEF\xBB\xBF", "x,y,z\n", "\xEF\xBB\xBF# exported\nx, y, z\n"}) {
        INFO(start);
        const hullkit::PointsResult parsed = hullkit::parse_points(start + lines.text, "p.csv", 1);
        REQUIRE(parsed.ok());
        CHECK(parsed.xyz == lines.xyz);
        CHECK(parsed.warnings.size() == (start.find('x') == std::string::npos ? 0u : 1u));
        check_agrees(start + lines.text, "p.csv", true);
        check_agrees(start + lines.text, "p.csv", false, nullptr, {Via::Stream, Via::File});
    }
}

TEST_CASE("point_reader: a byte-order mark before a PLY or glTF header is judged as read_points judges it", "[threads]") {
    // The format is decided on the bytes as they are (found by fuzzing: the reader skipped the mark
    // first and read a binary glTF that read_points called binary data); the mark skipped only
    // before text. tests/data/fuzz/points-bom-before-*.txt are the fuzzer's inputs.
    const std::string bom = "\xEF\xBB\xBF";
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                            "property float z\nend_header\n1 2 3\n";
    std::string glb("glTF\x02\0\0\0\x40\x03\0\0", 12);
    for (const std::string& body : {ply, glb, std::string("0 0 0\n1 2 3\n")}) {
        for (const char* name : {"p.txt", "p.ply"}) {
            INFO(name << " " << body.substr(0, 4));
            check_agrees(bom + body, name, false, nullptr, {Via::Memory, Via::Stream, Via::File});
            check_agrees(bom + body, name, true, nullptr, {Via::Memory, Via::Stream, Via::File});
        }
    }
    // By name a PLY file: its first line must be "ply", without a mark (a PLY header is ASCII).
    CHECK(hullkit::read_points(bom + ply, "p.ply").error == "p.ply:1: expected \"ply\" on the first line");
    CHECK(hullkit::read_points(ply, "p.ply").ok());
    CHECK(!hullkit::read_points(bom + glb, "p.txt").ok());
}

TEST_CASE("point_reader: rbox counts are checked as parse_points checks them", "[threads]") {
    const PointLines lines = plain_lines(300, 5);
    const auto rbox = [&](std::size_t declared, const std::string& body) {
        return "3 rbox " + std::to_string(declared) + " D3\n" + std::to_string(declared) + "\n" + body;
    };
    check_agrees(rbox(300, lines.text), "r.txt", true);
    check_agrees(rbox(300, lines.text + "\n# done\n\n"), "r.txt", true);
    // Too many: the message names the first line past the count, wherever a batch ends.
    for (std::size_t declared : {0, 1, 7, 150, 299}) {
        INFO("declared " << declared);
        const std::string text = rbox(declared, lines.text);
        const PointsResult expected = hullkit::parse_points(text, "r.txt", 1);
        CHECK(expected.error == "r.txt:" + std::to_string(declared + 3) + ": more points than the " +
                                    std::to_string(declared) + " declared on line 2");
        const std::vector<double> allowed(lines.xyz.begin(), lines.xyz.begin() + 3 * declared);
        check_agrees(text, "r.txt", true, &allowed);
    }
    // Too many, the extra line a bad one: the count is exceeded first.
    check_agrees(rbox(2, "1 2 3\n4 5 6\n7 8\n"), "r.txt", true);
    // Too few, none, no count, another dimension.
    for (const std::string& text : {rbox(301, lines.text), rbox(5000, lines.text), std::string("3\n0\n"),
                                    std::string("3\n"), std::string("3 rbox\n# the count is missing\n"),
                                    std::string("2 rbox\n1\n1 2\n")}) {
        check_agrees(text, "r.txt", true);
    }
}

TEST_CASE("point_reader: OFF vertices, faces ignored, counts checked", "[threads]") {
    const PointLines lines = plain_lines(300, 6);
    std::string faces;
    for (int i = 0; i < 50; ++i) faces += "3 0 " + std::to_string(i + 1) + " " + std::to_string(i + 2) + " # face\n";
    check_agrees("OFF\n300 50 0\n" + lines.text + faces, "m.off", true);
    check_agrees("OFF 300 50 0\n" + lines.text + faces + "junk that nobody reads\n", "m.off", false);
    check_agrees("# c\nOFF\n\n300 50 0\n" + lines.text, "m.off", true);
    check_agrees("OFF\n200 0 0\n" + lines.text, "m.off", true);  // the rest read as faces: ignored
    check_agrees("OFF\n301 0 0\n" + lines.text, "m.off", true);  // one vertex short
    check_agrees("OFF\n0 0 0\n", "m.off", true);
    check_agrees("OFF\n", "m.off", true);
    check_agrees("COFF\n1 0 0\n1 2 3 255 0 0 255\n", "m.off", true);
    check_agrees("OFF\n3 0 0\n1 2 3\n4 5\n", "m.off", true);
}

TEST_CASE("point_reader: OBJ vertices, other records skipped", "[threads]") {
    const PointLines lines = plain_lines(300, 7);
    std::string obj = "# model\nmtllib m.mtl\no thing\n";
    std::size_t at = 0;
    for (std::size_t i = 0; i < 300; ++i) {
        const std::size_t end = lines.text.find('\n', at);
        obj += "v " + lines.text.substr(at, end - at) + (i % 3 == 0 ? " 1\n" : i % 3 == 1 ? " 0.5 0.5 0.5\n" : "\n");
        if (i % 10 == 0) obj += "vn 0 0 1\nf 1 2 3\n";
        at = end + 1;
    }
    const PointsResult expected = hullkit::parse_points(obj, "m.obj", 1);
    REQUIRE(expected.xyz == lines.xyz);
    check_agrees(obj, "m.obj", true);
    check_agrees(obj, "m.obj", false, nullptr, {Via::Stream});
    check_agrees(obj + "4 5 6\n", "m.obj", true, &lines.xyz);
    check_agrees(obj + "v 1 2\n", "m.obj", true, &lines.xyz);
    // Unknown records all through the file, in many pieces: one warning per kind, first lines and
    // counts as one pass finds them.
    std::string unknown = "648 1292\n";
    at = 0;
    for (std::size_t i = 0; i < 300; ++i) {
        const std::size_t end = lines.text.find('\n', at);
        unknown += "v " + lines.text.substr(at, end - at) + "\n";
        if (i % 7 == 3) unknown += "bogus record\n";
        if (i % 50 == 9) unknown += "zz\n";
        at = end + 1;
    }
    const PointsResult tallied = hullkit::parse_points(unknown, "fcl.obj", 1);
    REQUIRE(tallied.xyz == lines.xyz);
    REQUIRE(tallied.warnings.size() == 3);
    CHECK(tallied.warnings[0] == "skipped 1 unknown OBJ record \"648\" (first at line 1)");
    CHECK(tallied.warnings[1] == "skipped 43 unknown OBJ records \"bogus\" (first at line 6)");
    CHECK(tallied.warnings[2] == "skipped 6 unknown OBJ records \"zz\" (first at line 13)");
    check_agrees(unknown, "fcl.obj", true);
    check_agrees(unknown, "fcl.obj", false);
    check_agrees("o empty\nf 1 2 3\n", "m.obj", true);
}

TEST_CASE("point_reader: binary input and formats parse_points does not read", "[threads]") {
    std::string stl(84 + 2 * 50, '\0');
    stl.replace(0, 15, "binary STL head");
    stl[80] = 2;
    check_agrees(stl, "t.txt", true);
    check_agrees(stl, "t.txt", false);
    check_agrees(stl, "t.stl", false);
    check_agrees(std::string("1 2 3\n4 5\0", 10), "t.txt", true);
    check_agrees(std::string(5000, '#') + "\n1 2 \x01\x02\n", "t.txt", true);
    check_agrees("ply\nformat ascii 1.0\nelement vertex 1\nend_header\n0 0 0\n", "t.txt", true);
    check_agrees("solid cube\n  facet normal 0 0 1\n    outer loop\n", "t.txt", true);
    check_agrees("solid cube\n  facet normal 0 0 1\n    outer loop\n", "t.txt", false);
    // A first word "solid" further down, a NUL byte after the first 4096: read_points decides.
    check_agrees("# x\nsolid thing\n1 2 3\n", "t.txt", false);
    check_agrees("# x\nsolid thing\n1 2 3\n" + std::string(5000, ' ') + std::string(1, '\0'), "t.txt", false);
    check_agrees("1 2 3\n" + std::string(5000, ' ') + std::string(1, '\0') + "\n", "t.txt", false);
}

TEST_CASE("point_reader: a large text on many threads, and read_points_file on any thread count", "[threads]") {
    // Several MiB, so that batches hold many 1 MiB chunks; a comment longer than a chunk.
    PointLines lines = plain_lines(60000, 8);
    const PointLines tail = random_lines(60000, 9);
    lines.text += "# " + std::string(std::size_t{3} << 19, 'c') + "\n" + tail.text;
    lines.xyz.insert(lines.xyz.end(), tail.xyz.begin(), tail.xyz.end());
    for (std::size_t batch : {std::size_t{1} << 20, std::size_t{3} << 20, std::size_t{32} << 20}) {
        for (unsigned threads : {1u, 2u, 5u}) {
            for (Via via : {Via::Memory, Via::File, Via::Stream}) {
                INFO("batch " << batch << ", " << threads << " threads, via " << via_name(via));
                PointReaderOptions options;
                options.batch_bytes = batch;
                options.threads = threads;
                const Outcome got = read_via(lines.text, "big.txt", via, options);
                CHECK(got.error.empty());
                CHECK(same_bits(got.xyz, lines.xyz));
            }
        }
    }
    // Errors where threads parse the chunks around them: a count crossed, OFF vertices that end,
    // a bad line, all deep in the body.
    const PointLines plain = plain_lines(60000, 10);
    const std::vector<std::size_t> big_batches = {std::size_t{1} << 20, std::size_t{3} << 20};
    const std::vector<double> first(plain.xyz.begin(), plain.xyz.begin() + 3 * 41234);
    check_agrees("3 rbox\n41234\n" + plain.text, "r.txt", true, &first, {Via::Memory, Via::File, Via::Stream}, big_batches);
    check_agrees("OFF\n41234 0 0\n" + plain.text, "m.off", true, nullptr, {Via::Memory, Via::Stream}, big_batches);
    std::size_t bad = 0;
    for (int line = 0; line < 41234; ++line) bad = plain.text.find('\n', bad) + 1;
    check_agrees(plain.text.substr(0, bad) + "1 2 3 4\n" + plain.text.substr(bad), "x.txt", true, &first,
                 {Via::Memory, Via::Stream}, big_batches);

    hullkit_test::TempDir dir("point-reader");
    const std::string path = dir.file("big.txt");
    hullkit_test::write_text(path, "3 rbox\n60001\n" + plain.text);
    for (unsigned threads : {0u, 1u, 2u, 7u}) {
        const PointsResult result = hullkit::read_points_file(path, threads);
        CHECK(result.error == path + ":2: header declares 60001 points but the file has 60000");
        CHECK(result.xyz.empty());
    }
    hullkit_test::write_text(path, lines.text);
    for (unsigned threads : {0u, 1u, 2u, 7u}) {
        const PointsResult result = hullkit::read_points_file(path, threads);
        CHECK(result.error.empty());
        CHECK(same_bits(result.xyz, lines.xyz));
        CHECK(same_bits(hullkit::parse_points(lines.text, "big.txt", threads).xyz, lines.xyz));
    }
}

TEST_CASE("point_reader: the counters and the header's count", "[threads]") {
    const PointLines lines = plain_lines(5000, 10);
    const std::string text = "3 rbox 5000 D3\n5000\n" + lines.text;
    PointReaderOptions options;
    options.batch_bytes = 10000;
    options.threads = 2;
    PointReader reader(std::string_view(text), "r.txt", options);
    CHECK(reader.declared_points() == 5000);
    CHECK(reader.size() == text.size());
    std::vector<double> batch;
    std::size_t batches = 0;
    while (reader.next(&batch)) {
        ++batches;
        CHECK(batch.size() <= 3 * (10000 / 6 + 1));  // about one batch of text
    }
    CHECK(batches > 10);
    CHECK(reader.error().empty());
    CHECK(reader.points_read() == 5000);
    CHECK(reader.bytes_read() == text.size());
    CHECK(PointReader(std::string_view("OFF\n2 0 0\n1 2 3\n4 5 6\n"), "m.off").declared_points() == 2);
    CHECK(PointReader(std::string_view("1 2 3\n"), "p.txt").declared_points() == 0);
    // append_next keeps what the array holds.
    PointReader appending(std::string_view("1 2 3\n4 5 6\n"), "p.txt");
    std::vector<double> all = {9};
    CHECK(appending.append_next(&all));
    CHECK(all == std::vector<double>{9, 1, 2, 3, 4, 5, 6});
    CHECK_FALSE(appending.append_next(&all));
    CHECK(all.size() == 7);
    const std::string stl = hullkit_test::read_text(data_path("binary-two-triangles.stl"));
    PointReader whole(std::string_view(stl), "t.stl");
    all = {9};
    CHECK(whole.append_next(&all));
    CHECK(std::vector<double>(all.begin() + 1, all.end()) == hullkit::read_points(stl, "t.stl").xyz);
    // A reader moves.
    PointReader moved = std::move(whole);
    CHECK_FALSE(moved.next(&all));
    CHECK(moved.error().empty());
    CHECK(moved.points_read() == hullkit::read_points(stl, "t.stl").count());
}

TEST_CASE("point_reader: read errors and pipes", "[threads]") {
    // A directory opens but cannot be read.
    std::FILE* directory = std::fopen(data_path("degenerate").c_str(), "rb");
    REQUIRE(directory != nullptr);
    PointReader reader(directory, "dir");
    std::vector<double> batch;
    CHECK_FALSE(reader.next(&batch));
    CHECK(reader.error() == "dir: cannot read: Is a directory");
    std::fclose(directory);

    // A real pipe: text, PLY and binary STL from `cat`.
    const PointLines lines = random_lines(20000, 11);
    hullkit_test::TempDir dir("point-reader-pipe");
    const std::string text_path = dir.file("p.txt");
    hullkit_test::write_text(text_path, lines.text);
    const std::string stl_path = data_path("binary-two-triangles.stl");
    const std::string ply_path = data_path("route/plate.ply");
    for (const std::string& path : {text_path, stl_path, ply_path}) {
        for (unsigned threads : {1u, 3u}) {
            INFO(path << ", " << threads << " threads");
            std::FILE* pipe = popen(("cat " + hullkit_test::sh_quote(path)).c_str(), "r");
            REQUIRE(pipe != nullptr);
            PointReaderOptions options;
            options.threads = threads;
            options.batch_bytes = 50000;
            PointReader piped(pipe, "<stdin>", options);
            CHECK(piped.size() == 0);
            const Outcome got = read_all(piped, ~std::uint64_t{0});
            CHECK(pclose(pipe) == 0);
            const PointsResult expected = hullkit::read_points(hullkit_test::read_text(path), "<stdin>");
            CHECK(got.error == expected.error);
            CHECK(same_bits(got.xyz, expected.xyz));
            if (path == text_path) CHECK(same_bits(got.xyz, lines.xyz));
        }
    }
}

// ---- PLY ----

namespace {

/// A PLY scalar type and how to write a value of it.
struct PlyType {
    const char* name;
    int size;
    bool integer;
};

const PlyType kPlyTypes[] = {{"char", 1, true},   {"uchar", 1, true},  {"short", 2, true},  {"ushort", 2, true},
                             {"int", 4, true},    {"uint", 4, true},   {"float", 4, false}, {"double", 8, false},
                             {"int8", 1, true},   {"uint16", 2, true}, {"float32", 4, false}, {"float64", 8, false}};

/// Appends `value` as `type` in the file's format.
void put_value(std::string* out, const std::string& format, const PlyType& type, double value) {
    if (format == "ascii") {
        *out += hullkit::format_double(value) + " ";
        return;
    }
    unsigned char bytes[8];
    if (type.integer) {
        const auto word = static_cast<std::uint64_t>(static_cast<std::int64_t>(value));  // two's complement
        for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(word >> (8 * i));
    } else if (type.size == 4) {
        const float single = static_cast<float>(value);
        std::memcpy(bytes, &single, 4);
    } else {
        std::memcpy(bytes, &value, 8);
    }
    if (format == "binary_big_endian") std::reverse(bytes, bytes + type.size);
    out->append(reinterpret_cast<const char*>(bytes), type.size);
}

/// A PLY file of `count` vertices whose x y z are of `type` (integers for an integer type), with
/// an extra "confidence" property between x and y, an element "camera" before the vertices when
/// `element_before`, and triangles after them when `faces`.
std::string ply_file(const std::string& format, const PlyType& type, std::size_t count, bool element_before, bool faces,
                     std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::string out = "ply\nformat " + format + " 1.0\ncomment made by tests/io/point_reader.cpp\n";
    if (element_before) out += "element camera 2\nproperty uchar id\nproperty double scale\n";
    out += "element vertex " + std::to_string(count) + "\nproperty " + type.name + " x\nproperty ushort confidence\n" +
           "property " + type.name + " y\nproperty " + type.name + " z\n";
    const std::size_t triangles = faces && count >= 3 ? count - 2 : 0;
    if (faces) out += "element face " + std::to_string(triangles) + "\nproperty list uchar int vertex_indices\n";
    out += "end_header\n";
    const PlyType kUchar = {"uchar", 1, true}, kUshort = {"ushort", 2, true}, kInt = {"int", 4, true},
                  kDouble = {"double", 8, false};
    const std::string row_end = format == "ascii" ? "\n" : "";
    if (element_before) {
        for (int camera = 0; camera < 2; ++camera) {
            put_value(&out, format, kUchar, camera);
            put_value(&out, format, kDouble, 0.25 * camera);
            out += row_end;
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        double xyz[3];
        for (double& value : xyz) {
            value = type.integer ? static_cast<double>(random() % 100) : std::ldexp(static_cast<double>(random() % 100000) - 50000, -8);
        }
        put_value(&out, format, type, xyz[0]);
        put_value(&out, format, kUshort, static_cast<double>(random() % 60000));
        put_value(&out, format, type, xyz[1]);
        put_value(&out, format, type, xyz[2]);
        out += row_end;
    }
    for (std::size_t t = 0; t < triangles; ++t) {
        put_value(&out, format, kUchar, 3);
        for (std::size_t k = 0; k < 3; ++k) put_value(&out, format, kInt, static_cast<double>(t + k));
        out += row_end;
    }
    return out;
}

const char* const kPlyFormats[] = {"ascii", "binary_little_endian", "binary_big_endian"};

}  // namespace

TEST_CASE("point_reader: PLY point clouds and meshes of every type and byte order stream as read_points reads them",
          "[threads]") {
    for (const char* format : kPlyFormats) {
        for (const PlyType& type : kPlyTypes) {
            for (int layout = 0; layout < 4; ++layout) {
                const bool element_before = layout & 1, faces = layout & 2;
                const std::string ply = ply_file(format, type, 300, element_before, faces, 12);
                const PointsResult expected = hullkit::read_points(ply, "c.ply");
                INFO(format << " " << type.name << " layout " << layout << ": " << expected.error);
                REQUIRE(expected.ok());
                REQUIRE(expected.count() == 300);
                check_agrees(ply, "c.ply", false, nullptr, {Via::Memory, Via::Stream});
                check_agrees(ply, "upload", false, nullptr, {Via::Stream});  // PLY by content
            }
        }
    }
    PointReader reader(std::string_view(ply_file("binary_little_endian", kPlyTypes[6], 10, true, true, 13)), "c.ply");
    CHECK(reader.declared_points() == 10);
    // Larger than the first read, so that rows and lines straddle the reads.
    for (const char* format : kPlyFormats) {
        INFO(format);
        check_agrees(ply_file(format, kPlyTypes[3], 4000, true, true, 17), "c.ply", false, nullptr, {Via::Stream},
                     {64, 1000});
    }
}

TEST_CASE("point_reader: broken PLY files give read_points' message", "[threads]") {
    for (const char* format : kPlyFormats) {
        const std::string ply = ply_file(format, kPlyTypes[7], 40, true, true, 14);
        const std::size_t body = ply.find("end_header\n") + 11;
        INFO(format);
        // Cut anywhere: in the header, the camera rows, the vertices, the faces.
        for (std::size_t cut = 0; cut < ply.size(); cut += cut < body ? 7 : 3) {
            INFO("cut at " << cut);
            check_agrees(ply.substr(0, cut), "c.ply", false, nullptr, {Via::Stream});
        }
        check_agrees(ply + "xy", "c.ply", false, nullptr, {Via::Memory, Via::Stream});
        check_agrees(ply + "\n\n", "c.ply", false, nullptr, {Via::Stream});
        check_agrees(ply + "1 2\n", "c.ply", false, nullptr, {Via::Stream});
        // A value that is not a finite number in the 30th vertex, and a face index out of range.
        std::string bad = ply;
        if (std::string(format) == "ascii") {
            std::size_t at = body;
            for (int line = 0; line < 2 + 30; ++line) at = bad.find('\n', at) + 1;
            bad.insert(at, "nan ");
        } else {
            bad.replace(body + 2 * 9 + 30 * (8 + 2 + 8 + 8), 8, 8, '\xff');  // a NaN in either byte order
        }
        const PointsResult expected = hullkit::read_points(bad, "c.ply");
        REQUIRE_FALSE(expected.ok());
        check_agrees(bad, "c.ply", false, nullptr, {Via::Memory, Via::Stream});
        std::string bad_face = ply;
        bad_face.replace(bad_face.size() - (std::string(format) == "ascii" ? 3 : 4), 1, std::string(1, '7'));
        check_agrees(bad_face, "c.ply", false, nullptr, {Via::Stream});
    }
    check_agrees("ply\nformat ascii 1.0\nelement vertex 1\n", "a.ply", false);
    check_agrees("ply\r\nformat ascii 1.0\r\nelement vertex 1\r\nproperty float x\r\nproperty float y\r\n"
                 "property float z\r\nend_header\r\n1 2 3\r\n",
                 "a.ply", false);
    check_agrees("ply\rformat ascii 1.0\relement vertex 1\rproperty float x\rproperty float y\rproperty float z\r"
                 "end_header\r1 2 3\r",
                 "a.ply", false);
    // A header longer than the first read, with every kind of line end.
    std::string comments;
    while (comments.size() < 70000) comments += "comment " + std::string(70, 'c') + "\n";
    for (const char* end : {"\n", "\r\n", "\r"}) {
        std::string header = "ply\nformat ascii 1.0\n" + comments + "element vertex 2\nproperty float x\n"
                             "property float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n";
        std::string text;
        for (char c : header) text += c == '\n' ? std::string(end) : std::string(1, c);
        check_agrees(text, "a.ply", false, nullptr, {Via::Stream}, {64, 1000});
        check_agrees(text.substr(0, 50000), "a.ply", false, nullptr, {Via::Stream}, {1000});
    }
    check_agrees("not a ply\n", "a.ply", false);
    check_agrees("", "a.ply", false);
    check_agrees("ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                 "property float z\nend_header\n",
                 "a.ply", false);
    // The PLY reader is never reached in text-only mode.
    check_agrees(ply_file("ascii", kPlyTypes[6], 5, false, false, 15), "a.ply", true);
}

TEST_CASE("point_reader: TetGen .node files (by name), with attributes and markers", "[threads]") {
    const PointLines lines = plain_lines(300, 17);
    // The same points as "index x y z [attributes] [marker]" lines under a .node header.
    std::string node = "# a TetGen node file\n300 3 2 1\n", bare = "300 3\n";
    std::istringstream in(lines.text);
    std::size_t index = 1;
    for (std::string line; std::getline(in, line); ++index) {
        node += std::to_string(index) + " " + line + " 0.5 7 1\n";
        bare += std::to_string(index - 1) + "  " + line + "\n";
    }
    REQUIRE(hullkit::parse_points(node, "mesh.node", 1).xyz == lines.xyz);
    REQUIRE(hullkit::parse_points(bare, "mesh.node", 1).xyz == lines.xyz);
    check_agrees(node, "mesh.node", true, nullptr, {Via::File, Via::Stream}, {1000});
    check_agrees(bare, "mesh.node", true);
    // A line with the wrong number of fields, a 2D node file, fewer points than declared.
    const PointsResult wrong = hullkit::parse_points("2 3 0 1\n1 0 0 0 1\n2 1 1 1\n", "m.node", 1);
    REQUIRE(wrong.error == "m.node:3: expected 5 numbers (index, x, y, z, attributes, marker) as the header says, got 4");
    REQUIRE(hullkit::parse_points("4 2\n1 0 0\n", "m.node", 1).error == "m.node:1: .node file of dimension 2 (only 3D nodes are read)");
    REQUIRE_FALSE(hullkit::parse_points("3 3\n1 0 0 0\n", "m.node", 1).ok());
}
