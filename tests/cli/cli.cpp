// Tests that run the built `hullkit` command (HULLKIT_CLI_PATH) on temporary files, and check
// its hulls against Qhull's rbox/qconvex.
#include "hullkit/mesh_io.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_support.hpp"

using hullkit_test::data_path;
using hullkit_test::read_text;
using hullkit_test::run_cli;
using hullkit_test::run_shell;
using hullkit_test::RunResult;
using hullkit_test::sh_quote;
using hullkit_test::TempDir;
using hullkit_test::write_text;

namespace {

namespace fs = std::filesystem;

/// A failure must be exit code 2 and exactly one stderr line; returns that line.
std::string single_error_line(const RunResult& result) {
    INFO("stdout: " << result.out << "\nstderr: " << result.err);
    CHECK(result.exit_code == 2);
    std::vector<std::string> lines = result.err_lines();
    REQUIRE(lines.size() == 1);
    CHECK(result.err.back() == '\n');
    return lines[0];
}

bool relatively_close(double a, double b, double tolerance) {
    return std::fabs(a - b) <= tolerance * std::max(std::fabs(a), std::fabs(b));
}

// ---- a minimal JSON reader: enough to check that the output is well-formed and to read it ----

struct Json {
    enum class Kind { Null, Bool, Number, String, Array, Object } kind = Kind::Null;
    double number = 0.0;
    std::string text;
    std::vector<Json> items;
    std::vector<std::pair<std::string, Json>> members;  // in document order

    const Json& at(const std::string& key) const {
        for (const auto& member : members) {
            if (member.first == key) return member.second;
        }
        FAIL("JSON object has no key \"" << key << "\"");
        throw std::logic_error("unreachable");
    }
    std::vector<std::string> keys() const {
        std::vector<std::string> names;
        for (const auto& member : members) names.push_back(member.first);
        return names;
    }
};

class JsonParser {
public:
    explicit JsonParser(const std::string& text) : text_(text) {}

    /// Parses the whole text as one value (trailing whitespace allowed).
    Json parse_document() {
        Json value = parse_value();
        skip_space();
        if (pos_ != text_.size()) fail("trailing characters");
        return value;
    }

private:
    [[noreturn]] void fail(const std::string& what) {
        FAIL("invalid JSON at offset " << pos_ << ": " << what << "\n" << text_.substr(0, 200));
        throw std::logic_error("unreachable");
    }
    void skip_space() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    bool take(char c) {
        skip_space();
        if (pos_ < text_.size() && text_[pos_] == c) {
            ++pos_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c)) fail(std::string("expected '") + c + "'");
    }
    bool take_word(const std::string& word) {
        if (text_.compare(pos_, word.size(), word) != 0) return false;
        pos_ += word.size();
        return true;
    }

    Json parse_value() {
        skip_space();
        if (pos_ >= text_.size()) fail("unexpected end");
        Json value;
        char c = text_[pos_];
        if (c == '{') {
            value.kind = Json::Kind::Object;
            ++pos_;
            if (take('}')) return value;
            do {
                skip_space();
                std::string key = parse_string();
                expect(':');
                value.members.emplace_back(key, parse_value());
            } while (take(','));
            expect('}');
        } else if (c == '[') {
            value.kind = Json::Kind::Array;
            ++pos_;
            if (take(']')) return value;
            do value.items.push_back(parse_value());
            while (take(','));
            expect(']');
        } else if (c == '"') {
            value.kind = Json::Kind::String;
            value.text = parse_string();
        } else if (take_word("null")) {
            value.kind = Json::Kind::Null;
        } else if (take_word("true") || take_word("false")) {
            value.kind = Json::Kind::Bool;
        } else {
            value.kind = Json::Kind::Number;
            value.number = parse_number();
        }
        return value;
    }

    std::string parse_string() {
        if (pos_ >= text_.size() || text_[pos_] != '"') fail("expected a string");
        std::string out;
        for (++pos_; pos_ < text_.size() && text_[pos_] != '"'; ++pos_) {
            if (text_[pos_] == '\\') fail("escapes are not expected in hullkit output");
            out += text_[pos_];
        }
        if (pos_ >= text_.size()) fail("unterminated string");
        ++pos_;
        return out;
    }

    double parse_number() {
        // JSON's grammar: -?digits[.digits][(e|E)[+-]digits]; no nan, inf, hex or leading '+'.
        std::size_t start = pos_;
        auto digits = [&] {
            std::size_t first = pos_;
            while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
            if (pos_ == first) fail("expected digits");
        };
        if (text_[pos_] == '-') ++pos_;
        digits();
        if (pos_ < text_.size() && text_[pos_] == '.') {
            ++pos_;
            digits();
        }
        if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
            ++pos_;
            if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
            digits();
        }
        return std::strtod(text_.substr(start, pos_ - start).c_str(), nullptr);
    }

    const std::string& text_;
    std::size_t pos_ = 0;
};

Json parse_json(const std::string& text) { return JsonParser(text).parse_document(); }

/// The --stats line: exactly these keys, in this order.
Json parse_stats(const RunResult& result) {
    INFO("stderr: " << result.err);
    std::vector<std::string> lines = result.err_lines();
    REQUIRE(lines.size() == 1);
    Json stats = parse_json(lines[0]);
    REQUIRE(stats.kind == Json::Kind::Object);
    CHECK(stats.keys() == std::vector<std::string>{"points", "vertices", "faces", "volume", "area",
                                                   "algorithm", "seconds", "streamed", "threads"});
    return stats;
}

/// The numbers on line `line_index` (0-based) of a command's output.
std::vector<double> numbers_on_line(const std::string& text, std::size_t line_index) {
    std::istringstream in(text);
    std::string line;
    for (std::size_t i = 0; i <= line_index; ++i) REQUIRE(std::getline(in, line));
    std::istringstream fields(line);
    std::vector<double> numbers;
    for (double v; fields >> v;) numbers.push_back(v);
    return numbers;
}

void require_on_path(const TempDir& dir, const std::string& tool) {
    RunResult found = run_shell(dir, "command -v " + tool);
    if (found.exit_code != 0) {
        FAIL(tool << " is not on PATH: install the Debian package qhull-bin (scripts/setup.sh "
                     "does) to cross-check hulls against Qhull");
    }
}

}  // namespace

// ---- usage and errors ----

TEST_CASE("cli: --help, hull --help and --version") {
    TempDir dir("hullkit-cli");
    RunResult help = run_cli(dir, {"--help"});
    CHECK(help.exit_code == 0);
    CHECK(help.out.rfind("Usage: hullkit <command>", 0) == 0);
    CHECK(help.err.empty());

    RunResult hull_help = run_cli(dir, {"hull", "--help"});
    CHECK(hull_help.exit_code == 0);
    CHECK(hull_help.out.rfind("Usage: hullkit hull [INPUT...|-]", 0) == 0);
    CHECK(hull_help.out.find("--algorithm NAME    hull algorithm: quickhull (default), giftwrap\n") !=
          std::string::npos);

    RunResult version = run_cli(dir, {"--version"});
    CHECK(version.exit_code == 0);
    CHECK(version.out == "hullkit 0.1.0\n");
}

TEST_CASE("cli: every command's --help has one layout: usage first, options with their defaults, ranges in one wording") {
    TempDir dir("hullkit-cli");
    // The commands the main help lists.
    const std::string main_help = run_cli(dir, {"--help"}).out;
    const std::size_t list = main_help.find("Commands:\n");
    REQUIRE(list != std::string::npos);
    std::vector<std::string> commands;
    {
        std::istringstream lines(main_help.substr(list + 10, main_help.find("\n\n", list) - list - 10));
        for (std::string line; std::getline(lines, line);) {
            std::istringstream words(line);
            std::string name;
            if (words >> name) commands.push_back(name);
        }
    }
    CHECK(commands.size() >= 5);
    const std::regex option_line(R"(^  (-\w, )?(--[a-z0-9-]+)( [A-Z]+)?)");
    const std::regex range(R"(a whole number\s+from\s+(\d+)\s+to\s+(\d+))");
    for (const std::string& command : commands) {
        const RunResult help = run_cli(dir, {command, "--help"});
        INFO(command << " --help:\n" << help.out);
        CHECK(help.exit_code == 0);
        CHECK(help.err.empty());
        CHECK(help.out.rfind("Usage: hullkit " + command + " ", 0) == 0);
        CHECK(run_cli(dir, {command, "-h"}).out == help.out);
        CHECK(help.out.find("Exit status: ") != std::string::npos);
        // One block of options, --help last; then the exit status.
        const std::size_t options = help.out.find("\nOptions:\n");
        REQUIRE(options != std::string::npos);
        const std::size_t block_end = help.out.find("\n\n", options + 1);
        REQUIRE(block_end != std::string::npos);
        const std::string block = help.out.substr(options + 9, block_end - options - 9);  // from its first line's '\n'
        CHECK_THAT(block, Catch::EndsWith("\n  -h, --help          show this help"));
        CHECK(help.out.find("\nExit status: ", block_end) != std::string::npos);
        // Each option with a value says its default (the output's: standard output); a number's
        // range is worded as its error message words it, and that message is the one given.
        std::vector<std::string> entries;
        std::istringstream lines(block);
        for (std::string line; std::getline(lines, line);) {
            if (line.empty()) continue;
            if (line.rfind("  -", 0) == 0 || entries.empty()) {
                entries.push_back(line);
            } else {
                entries.back() += " " + line;
            }
        }
        for (const std::string& entry : entries) {
            std::smatch option;
            REQUIRE(std::regex_search(entry, option, option_line));
            const std::string name = option[2], value = option[3];
            if (value.empty()) continue;
            INFO(entry);
            CHECK((entry.find("default") != std::string::npos || entry.find("instead of standard output") != std::string::npos));
            if (value != " N" && value != " MB") continue;
            std::smatch bounds;
            REQUIRE(std::regex_search(entry, bounds, range));
            CHECK(single_error_line(run_cli(dir, {command, name, "abc"})) ==
                  "hullkit: option " + name + " needs a whole number from " + bounds[1].str() + " to " + bounds[2].str() +
                      ", got \"abc\"");
        }
        // "whole number" only ever in those words.
        std::size_t whole = 0, worded = 0;
        for (std::size_t at = help.out.find("whole number"); at != std::string::npos; at = help.out.find("whole number", at + 1)) ++whole;
        const std::regex worded_range(R"(a whole number\s+from\s+\d+\s+to\s+\d+)");
        for (auto it = std::sregex_iterator(help.out.begin(), help.out.end(), worded_range); it != std::sregex_iterator(); ++it) {
            ++worded;
        }
        CHECK(whole == worded);
    }
}

TEST_CASE("cli: a bad option value names the option, in every command (route --samples abc)") {
    TempDir dir("hullkit-cli");
    CHECK(single_error_line(run_cli(dir, {"route", "scene.json", "--samples", "abc"})) ==
          "hullkit: option --samples needs a whole number from 0 to 1000000, got \"abc\"");
    CHECK(single_error_line(run_cli(dir, {"route", "scene.json", "--samples=-3"})) ==
          "hullkit: option --samples needs a whole number from 0 to 1000000, got \"-3\"");
    CHECK(single_error_line(run_cli(dir, {"route", "--threads", "1025", "scene.json"})) ==
          "hullkit: option --threads needs a whole number from 0 to 1024, got \"1025\"");
    CHECK(single_error_line(run_cli(dir, {"delaunay", "--threads", "two"})) ==
          "hullkit: option --threads needs a whole number from 0 to 1024, got \"two\"");
    CHECK(single_error_line(run_cli(dir, {"hull", "--threads", "two"})) ==
          "hullkit: option --threads needs a whole number from 0 to 1024, got \"two\"");
    CHECK(single_error_line(run_cli(dir, {"hull", "--memory", "0"})) ==
          "hullkit: option --memory needs a whole number from 1 to 1073741824, got \"0\"");
    CHECK(single_error_line(run_cli(dir, {"route", "scene.json", "--samples"})) ==
          "hullkit: option --samples needs a value (try 'hullkit route --help')");
    CHECK(single_error_line(run_cli(dir, {"route"})) == "hullkit: route needs one SCENE file, got 0 (try 'hullkit route --help')");
    CHECK(single_error_line(run_cli(dir, {"route", "a.json", "--bogus"})) ==
          "hullkit: unknown option \"--bogus\" (try 'hullkit route --help')");
}

TEST_CASE("cli: malformed file exits 2 with one line naming file and line") {
    TempDir dir("hullkit-cli");
    const std::string path = data_path("malformed-line3.txt");
    RunResult result = run_cli(dir, {"hull", path});
    CHECK(single_error_line(result) == "hullkit: " + path + ":3: expected 3 coordinates, got 2");
    CHECK(result.out.empty());

    const std::string bad_number = dir.file("bad.off");
    write_text(bad_number, "OFF\n4 0 0\n0 0 0\n1 0 0\n1.2.3 1 0\n0 0 1\n");
    CHECK(single_error_line(run_cli(dir, {"hull", bad_number})) ==
          "hullkit: " + bad_number + ":5: coordinate \"1.2.3\" is not a number");
}

TEST_CASE("cli: usage problems exit 2 with one line") {
    TempDir dir("hullkit-cli");
    const std::string tetra = data_path("tetra.off");
    CHECK(single_error_line(run_cli(dir, {"hull", "--frobnicate", tetra})) ==
          "hullkit: unknown option \"--frobnicate\" (try 'hullkit hull --help')");
    CHECK(single_error_line(run_cli(dir, {"hull", tetra, "--algorithm", "quickhull9"})) ==
          "hullkit: unknown algorithm \"quickhull9\" (known: quickhull, giftwrap)");
    CHECK(single_error_line(run_cli(dir, {"hull", tetra, "--algorithm=nope"})) ==
          "hullkit: unknown algorithm \"nope\" (known: quickhull, giftwrap)");
    CHECK(single_error_line(run_cli(dir, {"hull", tetra, "--format", "ply"})) ==
          "hullkit: unknown format \"ply\" (known: off, obj, json, xyz, glb, normals)");
    CHECK(single_error_line(run_cli(dir, {"hull", tetra, "-o"})) == "hullkit: option -o needs a value");
    // Several INPUTs are one cloud: the tetrahedron twice is the tetrahedron (repeats: lowest index).
    CHECK(run_cli(dir, {"hull", tetra, tetra}).out == run_cli(dir, {"hull", tetra}).out);
    CHECK(single_error_line(run_cli(dir, {"frobnicate"})) ==
          "hullkit: unknown command \"frobnicate\" (try 'hullkit --help')");
    CHECK(single_error_line(run_cli(dir, {"--frobnicate"})) ==
          "hullkit: unknown option \"--frobnicate\" (try 'hullkit --help')");
    CHECK(single_error_line(run_cli(dir, {})) == "hullkit: missing command (try 'hullkit --help')");
}

TEST_CASE("cli: unreadable input and unwritable output exit 2") {
    TempDir dir("hullkit-cli");
    const std::string missing = dir.file("missing.txt");
    CHECK(single_error_line(run_cli(dir, {"hull", missing})) ==
          "hullkit: " + missing + ": cannot open: No such file or directory");
    CHECK(single_error_line(run_cli(dir, {"hull", data_path("")})).find(": cannot read: ") !=
          std::string::npos);
    const std::string unwritable = dir.file("no-such-dir/out.off");
    CHECK(single_error_line(run_cli(dir, {"hull", data_path("tetra.off"), "-o", unwritable})) ==
          "hullkit: " + unwritable + ": cannot open for writing: No such file or directory");
}

TEST_CASE("cli: hull errors are prefixed with the input name") {
    TempDir dir("hullkit-cli");
    SECTION("a non-finite coordinate names the line and the point") {
        const std::string path = dir.file("nan.txt");
        write_text(path, "0 0 0\n1 0 0\n0 1 0\n# a comment\n0 0 1\n1 nan 1\n");
        CHECK(single_error_line(run_cli(dir, {"hull", path})) ==
              "hullkit: " + path + ":6: coordinate \"nan\" of point 4 is not a finite number");
    }
    SECTION("from stdin, the input is called <stdin>") {
        const std::string path = dir.file("inf.txt");
        write_text(path, "0 0 0\n1 0 0\n0 1 0\n-inf 0 1\n");
        CHECK(single_error_line(run_cli(dir, {"hull"}, path)) ==
              "hullkit: <stdin>:4: coordinate \"-inf\" of point 3 is not a finite number");
    }
    SECTION("a number beyond the double range says so") {
        const std::string path = dir.file("big.txt");
        write_text(path, "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1e400 1\n");
        CHECK(single_error_line(run_cli(dir, {"hull", path})) ==
              "hullkit: " + path + ":5: coordinate \"1e400\" of point 4 is out of the double range");
        // The point is counted within its file; the file names which.
        CHECK(single_error_line(run_cli(dir, {"hull", data_path("tetra.off"), path})) ==
              "hullkit: " + path + ":5: coordinate \"1e400\" of point 4 is out of the double range");
    }
}

TEST_CASE("cli: no points is an empty hull (dimension -1), exit 0, in every format") {
    TempDir dir("hullkit-cli");
    const std::string empty = dir.file("empty.txt");
    for (const std::string text : {"", "# nothing here\n\n", "3 rbox 0 D3\n0\n", "OFF\n0 0 0\n", "x,y,z\n"}) {
        INFO(text);
        write_text(empty, text);
        RunResult off = run_cli(dir, {"hull", empty, "--quiet"});
        CHECK(off.exit_code == 0);
        CHECK(off.err.empty());
        CHECK(off.out == "OFF\n0 0 0\n");
        CHECK(run_cli(dir, {"hull", "-"}, empty).out == off.out);  // standard input too
    }
    write_text(empty, "");
    RunResult json = run_cli(dir, {"hull", empty, "--format", "json", "--stats"});
    REQUIRE(json.exit_code == 0);
    const Json hull = parse_json(json.out);
    CHECK(hull.at("dimension").number == -1);
    CHECK(hull.at("points").items.empty());
    CHECK(hull.at("vertices").items.empty());
    CHECK(hull.at("triangles").items.empty());
    CHECK(hull.at("equations").items.empty());
    CHECK(hull.at("volume").number == 0);
    CHECK(hull.at("area").number == 0);
    const Json stats = parse_stats(json);
    CHECK(stats.at("points").number == 0);
    CHECK(stats.at("vertices").number == 0);
    CHECK(stats.at("faces").number == 0);
    RunResult obj = run_cli(dir, {"hull", empty, "--format", "obj"});
    CHECK(obj.exit_code == 0);
    CHECK(obj.out.empty());  // an OBJ without records
    RunResult xyz = run_cli(dir, {"hull", empty, "--vertices-only"});
    CHECK(xyz.exit_code == 0);
    CHECK(hullkit::parse_points(xyz.out, "back.xyz").count() == 0);  // reads back as no points
    RunResult glb = run_cli(dir, {"hull", empty, "-o", dir.file("empty.glb")});
    CHECK(glb.exit_code == 0);
    CHECK(read_text(dir.file("empty.glb")).rfind("glTF", 0) == 0);
    // The empty hull of the empty input verifies, and is what a whole input plus an empty one gives.
    write_text(dir.file("hull.off"), "OFF\n0 0 0\n");
    CHECK(run_cli(dir, {"verify", empty, dir.file("hull.off")}).exit_code == 0);
    CHECK(run_cli(dir, {"hull", data_path("tetra.off"), empty}).out == run_cli(dir, {"hull", data_path("tetra.off")}).out);
}

TEST_CASE("cli: CSV with a header row and a UTF-8 byte-order mark is read, the header reported as skipped") {
    TempDir dir("hullkit-cli");
    const std::string csv = dir.file("points.csv");
    write_text(csv, "\xEF\xBB\xBFx,y,z\n0,0,0\n1,0,0\n0,1,0\n0,0,1\n0.1,0.1,0.1\n");
    RunResult result = run_cli(dir, {"hull", csv});
    REQUIRE(result.exit_code == 0);
    CHECK(result.out == run_cli(dir, {"hull", data_path("tetra.off")}).out);
    CHECK(result.err == "hullkit: warning: " + csv + ": skipped header line 1: x,y,z\n");
    CHECK(run_cli(dir, {"hull", csv, "--quiet"}).err.empty());
    // A BOM alone before plain points; line numbers in messages are unchanged by it.
    write_text(csv, "\xEF\xBB\xBF" "0 0 0\n1 0\n");
    CHECK(single_error_line(run_cli(dir, {"hull", csv})) == "hullkit: " + csv + ":2: expected 3 coordinates, got 2");
}

// ---- successful runs ----

TEST_CASE("cli: lower-dimensional point sets give a flat hull, not an error") {
    // hullkit::hull reports coplanar, collinear and single points as hulls of dimension 2, 1, 0
    // (hull.hpp); the CLI writes them like any other hull.
    TempDir dir("hullkit-cli");
    struct Case {
        std::string points;
        std::size_t vertices, faces;
        double area;
    };
    const std::vector<Case> cases = {
        {"0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0.5 0\n", 4, 2, 1.0},  // square with its centre
        {"0 0 0\n2 0 0\n0 0 1\n", 3, 1, 1.0},                      // three points
        {"0 0 0\n1 1 1\n2 2 2\n", 2, 0, 0.0},                      // a segment
        {"3 2 1\n3 2 1\n", 1, 0, 0.0},                              // one point, repeated
    };
    for (const Case& c : cases) {
        const std::string path = dir.file("flat.txt");
        write_text(path, c.points);
        RunResult result = run_cli(dir, {"hull", path, "--stats"});
        INFO(c.points << result.err);
        REQUIRE(result.exit_code == 0);
        Json stats = parse_stats(result);
        CHECK(stats.at("vertices").number == c.vertices);
        CHECK(stats.at("faces").number == c.faces);
        CHECK(stats.at("volume").number == 0.0);
        CHECK(stats.at("area").number == Approx(c.area).epsilon(1e-12));
        hullkit::MeshResult mesh = hullkit::read_off_mesh(result.out, "stdout.off");
        INFO(mesh.error);
        REQUIRE(mesh.ok());
        CHECK(mesh.point_count() == c.vertices);
        CHECK(mesh.triangle_count() == c.faces);
    }
}


TEST_CASE("cli: stdin input gives the same hull as a file") {
    TempDir dir("hullkit-cli");
    const std::string cube = data_path("cube.obj");
    RunResult from_file = run_cli(dir, {"hull", cube});
    RunResult from_stdin = run_cli(dir, {"hull"}, cube);
    RunResult from_dash = run_cli(dir, {"hull", "-"}, cube);
    REQUIRE(from_file.exit_code == 0);
    CHECK(from_file.err.empty());
    CHECK(from_stdin.exit_code == 0);
    CHECK(from_dash.exit_code == 0);
    CHECK(from_stdin.out == from_file.out);
    CHECK(from_dash.out == from_file.out);

    hullkit::MeshResult mesh = hullkit::read_off_mesh(from_file.out, "stdout");
    INFO(mesh.error);
    REQUIRE(mesh.ok());
    CHECK(mesh.point_count() == 8);
    CHECK(mesh.triangle_count() == 12);
}

TEST_CASE("cli: -o writes the file, the format follows the extension unless --format is given") {
    TempDir dir("hullkit-cli");
    const std::string tetra = data_path("tetra.off");
    struct Case {
        std::vector<std::string> extra;
        std::string output;
        std::string starts_with;
    };
    const std::vector<Case> cases = {
        {{}, "hull.off", "OFF\n4 4 0\n"},
        {{}, "hull.obj", "v 0 0 0\n"},
        {{}, "hull.JSON", "{\"vertices\":[0,1,2,3],"},
        {{}, "hull.txt", "OFF\n"},
        {{"--format", "obj"}, "hull.json", "v 0 0 0\n"},
        {{"--format=json"}, "hull.off", "{\"vertices\":"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = {"hull", tetra, "-o", dir.file(c.output)};
        args.insert(args.end(), c.extra.begin(), c.extra.end());
        RunResult result = run_cli(dir, args);
        INFO(c.output << " " << result.err);
        CHECK(result.exit_code == 0);
        CHECK(result.out.empty());
        CHECK(result.err.empty());
        CHECK(read_text(dir.file(c.output)).rfind(c.starts_with, 0) == 0);
    }
    // A failed run leaves no output file behind.
    RunResult failed = run_cli(dir, {"hull", data_path("malformed-line3.txt"), "-o", dir.file("no.off")});
    CHECK(failed.exit_code == 2);
    CHECK_FALSE(fs::exists(dir.file("no.off")));
}

TEST_CASE("cli: --stats writes one JSON line with the hull's numbers") {
    TempDir dir("hullkit-cli");
    RunResult result = run_cli(dir, {"hull", data_path("cube.obj"), "--stats", "-o", dir.file("c.off"),
                                     "--algorithm", "giftwrap"});
    REQUIRE(result.exit_code == 0);
    Json stats = parse_stats(result);
    CHECK(stats.at("points").number == 8);
    CHECK(stats.at("vertices").number == 8);
    CHECK(stats.at("faces").number == 12);
    CHECK(stats.at("volume").number == Approx(1.0).epsilon(1e-12));
    CHECK(stats.at("area").number == Approx(6.0).epsilon(1e-12));
    CHECK(stats.at("algorithm").text == "giftwrap");
    CHECK(stats.at("seconds").number >= 0.0);
    CHECK(stats.at("seconds").number < 60.0);

    RunResult by_default = run_cli(dir, {"hull", data_path("cube.obj"), "--stats", "-o", dir.file("d.off")});
    REQUIRE(by_default.exit_code == 0);
    Json default_stats = parse_stats(by_default);
    CHECK(default_stats.at("algorithm").text == hullkit::algorithm_name(hullkit::HullOptions{}.algorithm));
    CHECK(default_stats.at("vertices").number == 8);
    CHECK(default_stats.at("faces").number == 12);
    CHECK(default_stats.at("volume").number == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("cli: each output format parses back to the same hull") {
    TempDir dir("hullkit-cli");
    const std::string input = dir.file("points.txt");
    // A jittered grid plus random points: many interior points, awkward decimals.
    std::string text = "# test points\n";
    std::uint64_t state = 42;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;
    };
    for (int i = 0; i < 300; ++i) {
        text += hullkit::format_double(next()) + " " + hullkit::format_double(next() * 3) + " " +
                hullkit::format_double(next() / 7) + "\n";
    }
    write_text(input, text);
    std::vector<double> points = hullkit::parse_points(text, "points.txt").xyz;
    REQUIRE(points.size() == 900);

    RunResult json_run = run_cli(dir, {"hull", input, "--format", "json", "--stats"});
    REQUIRE(json_run.exit_code == 0);
    Json stats = parse_stats(json_run);
    Json hull = parse_json(json_run.out);
    REQUIRE(hull.kind == Json::Kind::Object);
    CHECK(hull.keys() == std::vector<std::string>{"vertices", "triangles", "points", "equations", "volume", "area", "dimension"});
    const auto& vertices = hull.at("vertices").items;
    const auto& triangles = hull.at("triangles").items;
    const auto& coordinates = hull.at("points").items;
    const auto& equations = hull.at("equations").items;
    REQUIRE(vertices.size() == stats.at("vertices").number);
    REQUIRE(triangles.size() == stats.at("faces").number);
    REQUIRE(coordinates.size() == vertices.size());
    REQUIRE(equations.size() == triangles.size());
    CHECK(triangles.size() == 2 * vertices.size() - 4);  // random points: a triangulated sphere
    CHECK(hull.at("volume").number == stats.at("volume").number);
    CHECK(hull.at("area").number == stats.at("area").number);
    std::vector<std::uint32_t> vertex_ids;
    for (std::size_t k = 0; k < vertices.size(); ++k) {
        auto id = static_cast<std::uint32_t>(vertices[k].number);
        REQUIRE(id < 300);
        vertex_ids.push_back(id);
        REQUIRE(coordinates[k].items.size() == 3);
        for (int c = 0; c < 3; ++c) CHECK(coordinates[k].items[c].number == points[3 * id + c]);
    }
    CHECK(std::is_sorted(vertex_ids.begin(), vertex_ids.end()));
    // Self-contained: the triangles index "points" (as OFF's faces index its vertex lines), each
    // plane is outward and holds its triangle's corners.
    std::vector<std::uint32_t> json_triangles;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        REQUIRE(triangles[t].items.size() == 3);
        REQUIRE(equations[t].items.size() == 4);
        double n[4];
        for (int k = 0; k < 4; ++k) n[k] = equations[t].items[k].number;
        CHECK(std::fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1) < 1e-15);
        for (const Json& corner : triangles[t].items) {
            const auto k = static_cast<std::uint32_t>(corner.number);
            REQUIRE(k < coordinates.size());
            json_triangles.push_back(k);
            const auto& p = coordinates[k].items;
            CHECK(std::fabs(n[0] * p[0].number + n[1] * p[1].number + n[2] * p[2].number + n[3]) < 1e-14);
        }
        for (std::size_t i = 0; i < 300; ++i) {
            CHECK(n[0] * points[3 * i] + n[1] * points[3 * i + 1] + n[2] * points[3 * i + 2] + n[3] < 1e-14);
        }
    }

    SECTION("OFF") {
        RunResult off = run_cli(dir, {"hull", input});
        REQUIRE(off.exit_code == 0);
        hullkit::MeshResult mesh = hullkit::read_off_mesh(off.out, "stdout.off");
        INFO(mesh.error);
        REQUIRE(mesh.ok());
        REQUIRE(mesh.point_count() == vertex_ids.size());
        REQUIRE(mesh.triangles.size() == json_triangles.size());
        CHECK(mesh.triangles == json_triangles);  // the same indices: OFF's vertex lines are JSON's points
        for (std::size_t k = 0; k < vertex_ids.size(); ++k) {
            for (int c = 0; c < 3; ++c) CHECK(mesh.xyz[3 * k + c] == points[3 * vertex_ids[k] + c]);
        }
    }
    SECTION("OBJ") {
        RunResult obj = run_cli(dir, {"hull", input, "--format", "obj"});
        REQUIRE(obj.exit_code == 0);
        hullkit::PointsResult obj_points = hullkit::parse_points(obj.out, "stdout.obj");
        INFO(obj_points.error);
        REQUIRE(obj_points.ok());
        REQUIRE(obj_points.count() == vertex_ids.size());
        for (std::size_t k = 0; k < vertex_ids.size(); ++k) {
            for (int c = 0; c < 3; ++c) CHECK(obj_points.xyz[3 * k + c] == points[3 * vertex_ids[k] + c]);
        }
        std::vector<std::uint32_t> obj_triangles;
        std::istringstream lines(obj.out);
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("f ", 0) != 0) continue;
            std::istringstream fields(line.substr(2));
            for (std::uint32_t index; fields >> index;) {
                REQUIRE(index >= 1);
                REQUIRE(index <= vertex_ids.size());
                obj_triangles.push_back(index - 1);
            }
        }
        CHECK(obj_triangles == json_triangles);
    }
}

// ---- cross-check against Qhull ----

namespace {

/// Runs rbox with `rbox_args`, then qconvex and hullkit (each algorithm) on the same file, and
/// compares the hull vertex set, the triangle count, the volume and the area.
void check_against_qconvex(const std::string& rbox_args) {
    TempDir dir("hullkit-cli");
    require_on_path(dir, "rbox");
    require_on_path(dir, "qconvex");
    const std::string input = dir.file("rbox.txt");
    RunResult rbox = run_shell(dir, "rbox " + rbox_args + " >" + sh_quote(input));
    REQUIRE(rbox.exit_code == 0);

    auto qconvex = [&](const std::string& options) {
        RunResult result = run_shell(dir, "qconvex " + options + " <" + sh_quote(input));
        INFO("qconvex " << options << ": " << result.err);
        REQUIRE(result.exit_code == 0);
        return result.out;
    };
    // FS: line 1 "0" (no integer sizes), line 2 "2 area volume".
    std::vector<double> sizes = numbers_on_line(qconvex("FS"), 1);
    REQUIRE(sizes.size() == 3);
    REQUIRE(sizes[0] == 2);
    const double qhull_area = sizes[1], qhull_volume = sizes[2];
    // Fx: the count of extreme points, then one index per line. (Fv's first line counts
    // facets, not vertices.)
    std::vector<std::uint32_t> qhull_vertices;
    {
        std::istringstream in(qconvex("Fx"));
        std::size_t count = 0;
        REQUIRE(in >> count);
        for (std::uint32_t index; in >> index;) qhull_vertices.push_back(index);
        REQUIRE(qhull_vertices.size() == count);
        std::sort(qhull_vertices.begin(), qhull_vertices.end());
    }
    // Qt Fv: the count of triangulated facets first.
    std::vector<double> facet_count = numbers_on_line(qconvex("Qt Fv"), 0);
    REQUIRE(facet_count.size() == 1);
    // n: "4", the facet count, then "nx ny nz offset" per facet (random points: triangles), by normal.
    std::map<std::string, std::vector<double>> qhull_planes;
    auto normal_key = [](const std::vector<double>& plane) {
        char key[96];
        std::snprintf(key, sizeof key, "%.6f %.6f %.6f", plane[0] + 0.0, plane[1] + 0.0, plane[2] + 0.0);
        return std::string(key);
    };
    {
        std::istringstream in(qconvex("n"));
        std::size_t dimension = 0, count = 0;
        REQUIRE(in >> dimension >> count);
        REQUIRE(dimension == 4);
        std::vector<double> plane(4);
        while (in >> plane[0] >> plane[1] >> plane[2] >> plane[3]) qhull_planes[normal_key(plane)] = plane;
        REQUIRE(qhull_planes.size() == count);
    }

    for (const char* algorithm : {"quickhull", "giftwrap"}) {
        RunResult ours = run_cli(dir, {"hull", input, "--format", "json", "--stats", "--algorithm", algorithm});
        INFO("hullkit --algorithm " << algorithm << ": " << ours.err);
        REQUIRE(ours.exit_code == 0);
        Json stats = parse_stats(ours);
        CHECK(stats.at("algorithm").text == algorithm);
        Json hull = parse_json(ours.out);
        std::vector<std::uint32_t> our_vertices;
        for (const Json& v : hull.at("vertices").items) {
            our_vertices.push_back(static_cast<std::uint32_t>(v.number));
        }
        INFO("rbox " << rbox_args << ": hullkit volume " << stats.at("volume").number << " area "
                     << stats.at("area").number << "; qconvex volume " << qhull_volume << " area "
                     << qhull_area);
        CHECK(stats.at("vertices").number == qhull_vertices.size());
        CHECK(our_vertices == qhull_vertices);
        CHECK(stats.at("faces").number == facet_count[0]);
        // qconvex prints 16 significant digits, so 1e-9 leaves ample room for summation order.
        CHECK(relatively_close(stats.at("volume").number, qhull_volume, 1e-9));
        CHECK(relatively_close(stats.at("area").number, qhull_area, 1e-9));
        // --normals: qconvex n's facets, to 1e-12 (unit normals; offsets relative to 1 or more).
        RunResult normals = run_cli(dir, {"hull", input, "--normals", "--algorithm", algorithm});
        REQUIRE(normals.exit_code == 0);
        std::istringstream in(normals.out);
        std::size_t dimension = 0, count = 0;
        REQUIRE(in >> dimension >> count);
        CHECK(dimension == 4);
        CHECK(count == qhull_planes.size());
        std::vector<double> plane(4);
        std::size_t matched = 0;
        while (in >> plane[0] >> plane[1] >> plane[2] >> plane[3]) {
            const auto found = qhull_planes.find(normal_key(plane));
            REQUIRE(found != qhull_planes.end());
            for (int k = 0; k < 4; ++k) {
                CHECK(std::fabs(plane[k] - found->second[k]) <= 1e-12 * std::max(1.0, std::fabs(found->second[k])));
            }
            ++matched;
        }
        CHECK(matched == count);
    }
}

}  // namespace

TEST_CASE("cli: hull matches qconvex for rbox 2000 D3") { check_against_qconvex("2000 D3"); }

TEST_CASE("cli: hull matches qconvex for rbox 500 s D3") { check_against_qconvex("500 s D3"); }

TEST_CASE("cli: a binary file is named as such, without echoing its bytes") {
    TempDir dir("hullkit-cli");
    // Arbitrary binary data, from a file and through standard input: printable ASCII only.
    const std::string junk = dir.file("junk.bin");
    std::string bytes;
    for (int i = 0; i < 256; ++i) bytes += static_cast<char>(255 - i);
    write_text(junk, bytes);
    RunResult result = run_cli(dir, {"hull", junk});
    CHECK(single_error_line(result) == "hullkit: " + junk + ": not a point file: binary data (byte 0x7f at offset 128)");
    CHECK(result.out.empty());
    // A binary STL on standard input is read as a mesh (its vertices), as from a file.
    RunResult stl_in = run_cli(dir, {"hull"}, data_path("binary-two-triangles.stl"));
    CHECK(stl_in.exit_code == 0);
    CHECK(stl_in.out == run_cli(dir, {"hull", data_path("binary-two-triangles.stl")}).out);
    const std::string message = "hullkit: <stdin>: not a point file: binary data (byte 0x7f at offset 128)";  // bytes >= 0x80 may be UTF-8 text
    RunResult redirected = run_cli(dir, {"hull"}, junk);
    CHECK(single_error_line(redirected) == message);
    RunResult piped = run_shell(dir, "cat " + sh_quote(junk) + " | " + sh_quote(HULLKIT_CLI_PATH) + " hull");
    CHECK(single_error_line(piped) == message);
    for (unsigned char c : piped.err) CHECK((c == '\n' || (c >= 0x20 && c < 0x7f)));
}

TEST_CASE("cli: a PNG is named as what it is, exit 2, no bytes echoed, a PLY and an ASCII STL on stdin are read") {
    TempDir dir("hullkit-cli");
    // A PNG's signature and the start of its IHDR chunk.
    const std::string png = dir.file("picture.png");
    static const char kPng[] = "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10\0\0\0\x10\x08\x06\0\0\0";
    write_text(png, std::string(kPng, sizeof kPng - 1));
    RunResult result = run_cli(dir, {"hull", png});
    CHECK(single_error_line(result) == "hullkit: " + png + ": not a point file: binary data (byte 0x1a at offset 6)");
    CHECK(result.out.empty());
    for (unsigned char c : result.err) CHECK((c == '\n' || (c >= 0x20 && c < 0x7f)));

    // A PLY and an STL from standard input are read by their content, as files are (see the
    // next test): the hull of their vertices.
    const std::string ply = dir.file("mesh.ply");
    write_text(ply, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                    "end_header\n0 0 0\n");
    RunResult ply_in = run_cli(dir, {"hull", "--format", "json"}, ply);
    CHECK(ply_in.exit_code == 0);
    CHECK_THAT(ply_in.out, Catch::Contains("\"dimension\":0"));

    const std::string stl = dir.file("mesh.stl");
    write_text(stl, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
                    "endfacet\nendsolid t\n");
    RunResult stl_in = run_cli(dir, {"hull", "--format", "json"}, stl);
    CHECK(stl_in.exit_code == 0);
    CHECK_THAT(stl_in.out, Catch::Contains("\"dimension\":2"));
}

TEST_CASE("cli: PLY point clouds and STL files give the hull of their vertices, by name or by content") {
    TempDir dir("hullkit-cli");
    // A point cloud as scanners write it: vertices, no face element; one point inside.
    const std::string cloud = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.1 0.1 0.1\n";
    for (const std::string name : {"cloud.ply", "cloud.dat"}) {
        write_text(dir.file(name), cloud);
        RunResult result = run_cli(dir, {"hull", dir.file(name), "--stats", "-o", dir.file("c.off")});
        REQUIRE(result.exit_code == 0);
        Json stats = parse_stats(result);
        CHECK(stats.at("points").number == 5);
        CHECK(stats.at("vertices").number == 4);
        CHECK(stats.at("volume").number == Approx(1.0 / 6.0).epsilon(1e-12));
    }
    // A binary STL whose name says nothing (its size says STL): the cube's corners.
    const std::string stl = dir.file("upload.bin");
    {
        std::string bytes(80, ' ');
        const float corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
        const int triangles[4][3] = {{0, 1, 2}, {3, 5, 6}, {4, 7, 1}, {2, 7, 5}};  // every corner used
        const std::uint32_t count = 4;
        bytes.append(reinterpret_cast<const char*>(&count), 4);
        for (const auto& t : triangles) {
            const float normal[3] = {0, 0, 0};
            bytes.append(reinterpret_cast<const char*>(normal), 12);
            for (int k = 0; k < 3; ++k) bytes.append(reinterpret_cast<const char*>(corners[t[k]]), 12);
            bytes.append(2, '\0');
        }
        write_text(stl, bytes);
    }
    RunResult result = run_cli(dir, {"hull", stl, "--stats", "-o", dir.file("s.off")});
    REQUIRE(result.exit_code == 0);
    CHECK(parse_stats(result).at("vertices").number == 8);
    CHECK(parse_stats(result).at("volume").number == Approx(1.0).epsilon(1e-12));
    // The Delaunay command takes the cloud's x and y.
    write_text(dir.file("flat.ply"), "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                                     "property double z\nend_header\n0 0 5\n1 0 5\n0 1 5\n1 1.5 5\n");
    RunResult tri = run_cli(dir, {"delaunay", dir.file("flat.ply"), "--stats", "-o", dir.file("t.off")});
    REQUIRE(tri.exit_code == 0);
    CHECK(tri.err.find("\"points\":4,\"triangles\":2,") != std::string::npos);
    // A PLY without vertices is still an error naming the file.
    write_text(dir.file("empty.ply"), "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n");
    CHECK(single_error_line(run_cli(dir, {"hull", dir.file("empty.ply")})) ==
          "hullkit: " + dir.file("empty.ply") + ": the PLY header declares no \"vertex\" element");
}

TEST_CASE("cli: OBJ records that are not OBJ's are skipped with a warning line per kind, exit 0") {
    TempDir dir("hullkit-cli");
    // FCL's test meshes start with a "V F" count line.
    const std::string body = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.1 0.1 0.1\nf 1 2 3\n";
    write_text(dir.file("clean.obj"), body);
    write_text(dir.file("fcl.obj"), "5 1\n" + body + "bogus\nbogus\n");
    RunResult clean = run_cli(dir, {"hull", dir.file("clean.obj")});
    REQUIRE(clean.exit_code == 0);
    CHECK(clean.err.empty());
    RunResult warned = run_cli(dir, {"hull", dir.file("fcl.obj")});
    INFO(warned.err);
    CHECK(warned.exit_code == 0);
    CHECK(warned.out == clean.out);
    CHECK(warned.err_lines() == std::vector<std::string>{
                                    "hullkit: warning: " + dir.file("fcl.obj") + ": skipped 1 unknown OBJ record \"5\" (first at line 1)",
                                    "hullkit: warning: " + dir.file("fcl.obj") + ": skipped 2 unknown OBJ records \"bogus\" (first at line 8)"});
    // --quiet: no warnings either.
    RunResult quiet = run_cli(dir, {"hull", dir.file("fcl.obj"), "--quiet"});
    CHECK(quiet.exit_code == 0);
    CHECK(quiet.err.empty());
    // A malformed vertex is still an error.
    write_text(dir.file("bad.obj"), "5 1\nv 0 0\n");
    CHECK(single_error_line(run_cli(dir, {"hull", dir.file("bad.obj")})) ==
          "hullkit: " + dir.file("bad.obj") + ":2: expected \"v x y z [w]\", got 2 numbers");
    // The Delaunay command warns the same way.
    RunResult tri = run_cli(dir, {"delaunay", dir.file("fcl.obj"), "-o", dir.file("t.off")});
    CHECK(tri.exit_code == 0);
    CHECK(tri.err_lines().size() == 2);
}
