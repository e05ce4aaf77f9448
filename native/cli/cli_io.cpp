// See cli_io.hpp.
#include "cli_io.hpp"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <system_error>

#include <CLI/CLI.hpp>

#include "hullkit/mesh_io.hpp"
#include "hullkit/mesh_read.hpp"

namespace hullkit_cli {

std::string read_input(const std::string& path) {
    std::string text;
    if (path == "-") {
        char buffer[1 << 16];
        std::size_t n;
        while ((n = std::fread(buffer, 1, sizeof buffer, stdin)) > 0) text.append(buffer, n);
        if (std::ferror(stdin)) throw UsageError(std::string("<stdin>: cannot read: ") + std::strerror(errno));
        return text;
    }
    std::string error;
    if (!hullkit::read_file(path, &text, &error)) throw UsageError(error);
    return text;
}

hullkit::MeshResult read_mesh_file(const std::string& path) {
    const std::string bytes = read_input(path);
    hullkit::MeshResult mesh;
    switch (hullkit::detect_mesh_format(bytes, path)) {
        case hullkit::MeshFormat::Off:  // faces may be missing: a segment, a point, nothing
            mesh = hullkit::read_off_mesh(bytes, path);
            break;
        case hullkit::MeshFormat::Obj:
            mesh = hullkit::read_obj_mesh(bytes, path);
            if (!mesh.ok()) {
                // An OBJ without vertices (the empty hull's) is no mesh for the mesh reader, but
                // no points, and no error, for the point reader, which reads OBJ's vertices too.
                const hullkit::PointsResult points = hullkit::parse_points(bytes, path);
                if (points.ok() && points.xyz.empty()) mesh = hullkit::MeshResult();
            }
            break;
        default:  // PLY, STL, glTF, or a message saying what the file is not
            mesh = hullkit::read_mesh(bytes, path);
            break;
    }
    if (!mesh.ok()) throw UsageError(mesh.error);
    return mesh;
}

void write_output(const std::string& path, const std::string& text) {
    if (path.empty() || path == "-") {
        if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
            throw UsageError(std::string("<stdout>: cannot write: ") + std::strerror(errno));
        }
        return;
    }
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw UsageError(path + ": cannot open for writing: " + std::strerror(errno));
    bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    int saved_errno = errno;
    // fclose flushes, so a full disk may only show up here.
    if (std::fclose(file) != 0 && written) {
        written = false;
        saved_errno = errno;
    }
    if (!written) throw UsageError(path + ": cannot write: " + std::strerror(saved_errno));
}

void parse_or_throw(CLI::App& app, const std::vector<std::string>& args, const std::string& command) {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 consumes from the back
    const std::string hint = " (try 'hullkit " + command + " --help')";
    try {
        app.parse(reversed);
    } catch (const CLI::ExtrasError&) {
        const std::vector<std::string> extra = app.remaining();
        const std::string first = extra.empty() ? "?" : extra.front();
        if (first.size() > 1 && first[0] == '-') throw UsageError("unknown option \"" + first + "\"" + hint);
        throw UsageError("unexpected argument \"" + first + "\"" + hint);
    } catch (const CLI::ParseError& error) {
        // CLI11 says e.g. "--format: 1 required TEXT missing" for an option without its value.
        std::string what = error.what();
        const std::size_t colon = what.find(':');
        if (what.find("required") != std::string::npos && what.find("missing") != std::string::npos &&
            colon != std::string::npos) {
            throw UsageError("option " + what.substr(0, colon) + " needs a value" + hint);
        }
        throw UsageError(what + hint);
    }
}

std::uint64_t parse_whole_number(const std::string& value, const std::string& option, std::uint64_t min, std::uint64_t max) {
    std::uint64_t number = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
    if (value.empty() || error != std::errc() || end != value.data() + value.size() || number < min || number > max) {
        throw UsageError("option " + option + " needs a whole number from " + std::to_string(min) + " to " +
                         std::to_string(max) + ", got \"" + value + "\"");
    }
    return number;
}

void add_whole_number_option(CLI::App& app, const std::string& name, unsigned* value, unsigned min, unsigned max) {
    app.add_option_function<std::string>(name, [=](const std::string& text) {
           *value = static_cast<unsigned>(parse_whole_number(text, name, min, max));
       })->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

int print_usage_error(const std::string& message) {
    std::string line = message;
    for (char& c : line) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    std::fprintf(stderr, "hullkit: %s\n", line.c_str());
    return 2;
}

void print_warnings(const std::string& source, const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) {
        std::string line = (source.empty() ? "" : source + ": ") + warning;
        for (char& c : line) {
            if (c == '\n' || c == '\r') c = ' ';
        }
        std::fprintf(stderr, "hullkit: warning: %s\n", line.c_str());
    }
}

}  // namespace hullkit_cli
