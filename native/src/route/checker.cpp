// RouteChecker: the per-leg check, the legs spread over threads, and the public API. The scene's
// preparation and a leg's steps are in prepare.cpp, static_contact.cpp, sweep.cpp, clearance.cpp;
// legs that turn in turning.cpp.
//
// The geometry tested is always the traverse's triangles with vertices v + w rounded to doubles
// (w the offset) against the obstacles' triangles; every "do they meet" decision on it is exact
// (geometry.hpp). Over a leg from offset a to offset b a part triangle P sweeps
//     conv(P + a, P + b) = (P + a) u (P + b) u  U_edges  parallelogram(e + a, e + b),
// (a point of the sweep either stays in P for the whole sub-interval it is swept over, so it lies
// in a cap, or leaves P through an edge), so the sweep is 8 triangles and the sweep-versus-obstacle
// test is 8 exact triangle tests: no separating-axis tolerance anywhere. The part's solid is swept
// too: a closed part or obstacle cannot start to contain the other without their surfaces meeting
// first, so containment is only tested at the leg's start (exact ray parity).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "checker_internal.hpp"
#include "hull/parallel.hpp"
#include "hullkit/mesh_io.hpp"

namespace hullkit {

LegReport RouteChecker::Impl::check_leg(const std::vector<Part>& parts, const Vec& a, const Vec& b,
                                        const RouteOptions& options) const {
    LegReport leg;
    Found found;
    for (std::size_t pi = 0; pi < parts.size() && !found.found; ++pi) {
        if (static_touch(parts[pi], pi, a, &found)) found.found = true;
    }
    if (found.found) {
        leg.status = LegStatus::StartOverlap;
        leg.fraction_lo = leg.fraction_hi = 0.0;
        leg.position[0] = a.x, leg.position[1] = a.y, leg.position[2] = a.z;
        double w[3];
        leg.clearance = 0.0;
        if (!found.containment) {
            const Vec* p = &parts[found.part].tris[3 * found.part_slot];
            const Vec pa[3] = {p[0] + a, p[1] + a, p[2] + a};
            leg.clearance = triangle_distance(pa, &tris[3 * found.slot], w);
        }
    } else {
        for (std::size_t pi = 0; pi < parts.size(); ++pi) sweep_part(parts[pi], pi, a, b, &found);
        if (found.found) {
            leg.status = LegStatus::Hit;
            leg.fraction_lo = found.lo;
            leg.fraction_hi = found.hi;
            const Vec at = offset_at(a, b, found.lo);
            leg.position[0] = at.x, leg.position[1] = at.y, leg.position[2] = at.z;
            // The distance of the contact pair at the bracket's end: at most the margin.
            const Vec* p = &parts[found.part].tris[3 * found.part_slot];
            const Vec wh = offset_at(a, b, found.hi);
            Vec pieces[8][3];
            sweep_pieces(p, a, wh, pieces);
            double best = kInf, w[3];
            for (int k = 1; k < 8; ++k) best = std::min(best, triangle_distance(pieces[k], &tris[3 * found.slot], w));
            leg.clearance = std::min(best, margin);
        }
    }
    if (found.found) {
        leg.obstacle = found.obstacle;
        leg.triangle = found.triangle;
        leg.part = found.part;
    } else if (options.clearance) {
        Nearest best;
        for (std::size_t pi = 0; pi < parts.size(); ++pi) nearest_over_leg(parts[pi], pi, a, b, &best);
        leg.clearance = best.distance;
        leg.obstacle = best.obstacle;
        leg.triangle = best.triangle;
        leg.part = best.part;
        leg.fraction_lo = leg.fraction_hi = best.obstacle >= 0 ? best.fraction : 0.0;
        const Vec at = offset_at(a, b, leg.fraction_lo);
        leg.position[0] = at.x, leg.position[1] = at.y, leg.position[2] = at.z;
    } else {
        leg.position[0] = a.x, leg.position[1] = a.y, leg.position[2] = a.z;
    }
    if (options.samples > 0) {
        for (std::uint32_t k = 0; k <= options.samples; ++k) {
            const double t = k == options.samples ? 1.0 : static_cast<double>(k) / options.samples;
            const Vec w = offset_at(a, b, t);
            Found f;
            bool touch = false;
            for (std::size_t pi = 0; pi < parts.size() && !touch; ++pi) touch = static_touch(parts[pi], pi, w, &f);
            if (touch) {
                leg.sampled_hit = true;
                leg.sampled_fraction = t;
                break;
            }
        }
    }
    return leg;
}

void RouteChecker::Impl::check_legs(std::size_t count, const RouteOptions& options,
                                    const std::function<LegReport(std::size_t)>& leg, LegReport* legs) const {
    // Each leg's report is a function of its two waypoints, the options and this Impl, which
    // check() never modifies (every scratch buffer of the check path is local to check_leg and
    // what it calls), and goes to its own slot: how legs are spread over threads cannot change a
    // bit of it. New threads inherit the caller's floating-point environment (POSIX), so the
    // rounding is the same on every thread.
    const unsigned threads = detail::resolve_threads(options.threads, count);
    // Blocks of consecutive legs: a clear verdict takes a few microseconds, so handing out legs
    // one by one would be mostly overhead; about 8 blocks per thread (at most 64 legs each) keep
    // uneven legs balanced (a leg with clearance can cost 100 times a clear verdict) and the
    // progress reports frequent. The split depends on the leg and thread counts only.
    const std::size_t per_block =
        std::clamp<std::size_t>((count + 8 * std::size_t{threads} - 1) / (8 * std::size_t{threads}), 1, 64);
    const std::size_t blocks = (count + per_block - 1) / per_block;

    std::atomic<std::size_t> done{0};
    std::mutex progress_mutex;
    std::size_t reported = 0;  // guarded by progress_mutex
    auto legs_finished = [&](std::size_t finished) {
        const std::size_t total = done.fetch_add(finished, std::memory_order_acq_rel) + finished;
        if (!options.progress) return;
        // One report at a time, so that the counts arrive in increasing order. A thread that finds
        // another one reporting skips its turn (its legs are in the count the next report reads),
        // except the one finishing the last legs: the final count must be reported.
        std::unique_lock<std::mutex> lock(progress_mutex, std::defer_lock);
        if (total == count) {
            lock.lock();
        } else if (!lock.try_lock()) {
            return;
        }
        const std::size_t latest = done.load(std::memory_order_acquire);
        if (latest <= reported) return;  // a later report already covered these legs
        reported = latest;
        options.progress(latest);
    };
    detail::parallel_for(threads, blocks, [&](std::size_t block) {
        const std::size_t first = block * per_block, last = std::min(count, first + per_block);
        for (std::size_t k = first; k < last; ++k) legs[k] = leg(k);
        legs_finished(last - first);
    });
}

bool RouteChecker::Impl::check_offsets(const double* xyz, std::size_t count,
                                       std::string* message) const {
    for (std::size_t i = 0; i < 3 * count; ++i) {
        const double x = xyz[i];
        if (!std::isfinite(x)) {
            *message = "route: waypoint " + std::to_string(i / 3) + " has a non-finite coordinate";
            return false;
        }
        if (std::fabs(x) > kMaxCoordinate || (x != 0.0 && std::fabs(x) < kMinCoordinate)) {
            *message = "route: waypoint " + std::to_string(i / 3) +
                       " has a coordinate outside the supported range (0 or 2^-200..2^300 in "
                       "magnitude)";
            return false;
        }
    }
    return true;
}

// ---------------------------------------------------------------------------------------------

RouteChecker::RouteChecker(Scene scene) : impl_(std::make_unique<Impl>()) {
    const auto start = std::chrono::steady_clock::now();
    impl_->scene = std::move(scene);
    impl_->build();
    impl_->build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

RouteChecker::~RouteChecker() = default;
RouteChecker::RouteChecker(RouteChecker&&) noexcept = default;
RouteChecker& RouteChecker::operator=(RouteChecker&&) noexcept = default;

const std::string& RouteChecker::error() const { return impl_->error; }
const Scene& RouteChecker::scene() const { return impl_->scene; }
double RouteChecker::build_seconds() const { return impl_->build_seconds; }

namespace {

/// Unit quaternions from `wxyz` (4 per waypoint), normalized; false with a message when one is
/// not finite or not of length 1 within 1e-9.
bool read_rotations(const double* wxyz, std::size_t count, std::vector<Quat>* out, std::string* message) {
    out->resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const double* q = wxyz + 4 * k;
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]) || !std::isfinite(q[3])) {
            *message = "route: waypoint " + std::to_string(k) + ": the rotation has a non-finite component";
            return false;
        }
        const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(std::fabs(length - 1.0) <= 1e-9)) {
            *message = "route: waypoint " + std::to_string(k) + ": the rotation is not a unit quaternion (length " +
                       format_json_number(length) + ")";
            return false;
        }
        (*out)[k] = Quat{q[0] / length, q[1] / length, q[2] / length, q[3] / length};
    }
    return true;
}

Vec vec_at(const double* xyz, std::size_t k) { return {xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]}; }

}  // namespace

RouteReport RouteChecker::check(const double* route_xyz, std::size_t waypoint_count,
                                const RouteOptions& options) const {
    return check(route_xyz, nullptr, waypoint_count, options);
}

RouteReport RouteChecker::check(const double* route_xyz, const double* rotations_wxyz, std::size_t waypoint_count,
                                const RouteOptions& options) const {
    RouteReport report;
    report.build_seconds = impl_->build_seconds;
    report.clear = false;
    if (!impl_->error.empty()) {
        report.error = impl_->error;
        return report;
    }
    if (waypoint_count < 2) {
        report.error = "route: at least 2 waypoints are needed (got " +
                       std::to_string(waypoint_count) + ")";
        return report;
    }
    if (!impl_->check_offsets(route_xyz, waypoint_count, &report.error)) return report;
    std::vector<Quat> turns;
    if (rotations_wxyz && !read_rotations(rotations_wxyz, waypoint_count, &turns, &report.error)) return report;
    report.turned = rotations_wxyz != nullptr;
    const auto start = std::chrono::steady_clock::now();
    report.legs.resize(waypoint_count - 1);
    const Impl& im = *impl_;
    if (turns.empty()) {
        im.check_legs(report.legs.size(), options, [&](std::size_t k) {
            return im.check_leg(im.parts, vec_at(route_xyz, k), vec_at(route_xyz, k + 1), options);
        }, report.legs.data());
    } else {
        // Legs of one orientation translate the parts turned to it (built once per orientation,
        // before the threads start); the identity is the scene's own parts, bit for bit.
        std::vector<std::vector<Part>> turned;
        std::vector<std::int64_t> parts_of(report.legs.size(), -1);  // -1: the scene's; -2: a turning leg
        for (std::size_t k = 0; k < report.legs.size(); ++k) {
            if (!same_rotation(turns[k], turns[k + 1])) {
                parts_of[k] = -2;
            } else if (!rotation_of(turns[k]).identity) {
                for (std::size_t j = 0; j < k && parts_of[k] < 0; ++j) {
                    if (parts_of[j] >= 0 && same_rotation(turns[j], turns[k])) parts_of[k] = parts_of[j];
                }
                if (parts_of[k] < 0) {
                    parts_of[k] = static_cast<std::int64_t>(turned.size());
                    turned.push_back(im.turned_parts(turns[k]));
                }
            }
        }
        im.check_legs(report.legs.size(), options, [&](std::size_t k) {
            const Vec a = vec_at(route_xyz, k), b = vec_at(route_xyz, k + 1);
            if (parts_of[k] == -2) return im.check_turning_leg(LegMotion(a, b, turns[k], turns[k + 1], im.pivot), options);
            LegReport leg = im.check_leg(parts_of[k] < 0 ? im.parts : turned[parts_of[k]], a, b, options);
            leg.rotation[0] = turns[k].w, leg.rotation[1] = turns[k].x, leg.rotation[2] = turns[k].y,
            leg.rotation[3] = turns[k].z;
            return leg;
        }, report.legs.data());
    }
    // The aggregates in leg order, after the parallel loop: the same operations in the same order
    // for every thread count.
    report.clear = true;
    for (const LegReport& leg : report.legs) {
        report.clear = report.clear && leg.status == LegStatus::Clear;
        if (!std::isnan(leg.clearance)) report.min_clearance = std::min(report.min_clearance, leg.clearance);
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

RouteReport RouteChecker::check(const RouteOptions& options) const {
    const std::vector<double>& route = impl_->scene.route;
    if (route.size() % 3 != 0 && impl_->error.empty()) {
        RouteReport report;
        report.clear = false;
        report.error = "route: " + std::to_string(route.size()) + " coordinates are not whole waypoints";
        return report;
    }
    const std::vector<double>& rotations = impl_->scene.rotations;
    if (!rotations.empty() && rotations.size() != route.size() / 3 * 4 && impl_->error.empty()) {
        RouteReport report;
        report.clear = false;
        report.error = "route: " + std::to_string(rotations.size()) + " rotation numbers for " +
                       std::to_string(route.size() / 3) + " waypoints (4 per waypoint)";
        return report;
    }
    return check(route.data(), rotations.empty() ? nullptr : rotations.data(), route.size() / 3, options);
}

StaticContact RouteChecker::static_contact(const double offset[3], bool want_distance) const {
    std::string message;
    if (!impl_->error.empty() || !impl_->check_offsets(offset, 1, &message)) {
        StaticContact bad;
        bad.contact = true;
        return bad;
    }
    return impl_->contact_at(Vec(offset[0], offset[1], offset[2]), want_distance);
}

StaticContact RouteChecker::static_contact(const double offset[3], const double rotation_wxyz[4],
                                           bool want_distance) const {
    std::string message;
    std::vector<Quat> turn;
    if (!impl_->error.empty() || !impl_->check_offsets(offset, 1, &message) ||
        !read_rotations(rotation_wxyz, 1, &turn, &message)) {
        StaticContact bad;
        bad.contact = true;
        return bad;
    }
    Pose pose;
    pose.rotation = rotation_of(turn[0]);
    pose.offset = Vec(offset[0], offset[1], offset[2]);
    if (pose.rotation.identity) return impl_->contact_at(pose.offset, want_distance);
    return impl_->posed_contact(pose, want_distance);
}

void leg_pose(const double o0[3], const double q0[4], const double o1[3], const double q1[4], double t,
              double offset[3], double rotation[4]) {
    std::vector<Quat> ends;
    std::string message;
    const double both[8] = {q0[0], q0[1], q0[2], q0[3], q1[0], q1[1], q1[2], q1[3]};
    if (!read_rotations(both, 2, &ends, &message)) {  // normalized as the checker does; else as given
        ends = {Quat{q0[0], q0[1], q0[2], q0[3]}, Quat{q1[0], q1[1], q1[2], q1[3]}};
    }
    const LegMotion motion(Vec(o0[0], o0[1], o0[2]), Vec(o1[0], o1[1], o1[2]), ends[0], ends[1], Vec(0.0));
    const Vec o = motion.at(t).offset;
    const Quat q = motion.orientation(t);
    offset[0] = o.x, offset[1] = o.y, offset[2] = o.z;
    rotation[0] = q.w, rotation[1] = q.x, rotation[2] = q.y, rotation[3] = q.z;
}

StaticContact static_contact(const RouteChecker& checker, const double offset[3],
                             bool want_distance) {
    return checker.static_contact(offset, want_distance);
}

RouteReport check_route(Scene scene, const RouteOptions& options) {
    return RouteChecker(std::move(scene)).check(options);
}

}  // namespace hullkit
