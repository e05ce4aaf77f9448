// Small writers shared by the 2D commands (delaunay, triangulate): integers, and an SVG frame that
// maps plane coordinates (y up) to pixels (y down). No geometry here.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "hullkit/delaunay.hpp"

namespace hullkit_cli {

inline void append_uint(std::string& out, std::uint64_t value) {
    char buffer[24];
    out.append(buffer, static_cast<std::size_t>(std::snprintf(buffer, sizeof buffer, "%llu",
                                                              static_cast<unsigned long long>(value))));
}

/// Maps plane coordinates to SVG pixels: y up in the plane, y down on screen.
struct SvgFrame {
    double xmin = 0, ymin = 0, xmax = 1, ymax = 1;  ///< the plane rectangle shown (and Voronoi's clip)
    double scale = 1;
    static constexpr double kMargin = 12;  ///< pixels around the rectangle
    static constexpr double kSize = 800;   ///< pixels along the rectangle's longer side

    double x(double px) const { return kMargin + (px - xmin) * scale; }
    double y(double py) const { return kMargin + (ymax - py) * scale; }
    double width() const { return 2 * kMargin + (xmax - xmin) * scale; }
    double height() const { return 2 * kMargin + (ymax - ymin) * scale; }
};

/// The points' bounding box with a 5% border (a unit square around a single point).
inline SvgFrame frame_of(hullkit::PointSpan2 points) {
    SvgFrame frame;
    if (points.count == 0) return frame;
    frame.xmin = frame.xmax = points[0][0];
    frame.ymin = frame.ymax = points[0][1];
    for (std::size_t i = 1; i < points.count; ++i) {
        frame.xmin = std::min(frame.xmin, points[i][0]);
        frame.xmax = std::max(frame.xmax, points[i][0]);
        frame.ymin = std::min(frame.ymin, points[i][1]);
        frame.ymax = std::max(frame.ymax, points[i][1]);
    }
    double span = std::max(frame.xmax - frame.xmin, frame.ymax - frame.ymin);
    if (!(span > 0) || !std::isfinite(span)) span = 1;
    frame.xmin -= 0.05 * span;
    frame.xmax += 0.05 * span;
    frame.ymin -= 0.05 * span;
    frame.ymax += 0.05 * span;
    frame.scale = SvgFrame::kSize / (1.1 * span);
    return frame;
}

inline void append_pixel(std::string& out, double value) {
    char buffer[32];
    out.append(buffer, static_cast<std::size_t>(std::snprintf(buffer, sizeof buffer, "%.2f", value)));
}

inline void append_svg_point(std::string& out, const SvgFrame& frame, double x, double y) {
    append_pixel(out, frame.x(x));
    out += ',';
    append_pixel(out, frame.y(y));
}

/// The opening of an SVG picture of `frame` with a title and a white background.
inline std::string svg_header(const SvgFrame& frame, const std::string& title) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
    append_pixel(out, frame.width());
    out += "\" height=\"";
    append_pixel(out, frame.height());
    out += "\" viewBox=\"0 0 ";
    append_pixel(out, frame.width());
    out += ' ';
    append_pixel(out, frame.height());
    out += "\">\n<title>" + title + "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    return out;
}

}  // namespace hullkit_cli
