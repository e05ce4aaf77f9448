// Bowyer-Watson insertion: the incremental construction of the lower 4D hull of the lifted points,
// serial for small rounds and in deterministic partitions on threads for large ones.
//
// One insertion. A point p is located by a walk from the last new tetrahedron (a stochastic
// visibility walk: cross a face that has p strictly on its far side, starting the scan at a varying
// face, never back through the face just crossed). The tetrahedron reached holds p, or is a ghost
// whose hull face p sees; either way it conflicts with p. The cavity, every tetrahedron whose
// (perturbed) circumsphere holds p, is grown from it over faces; it is star-shaped from p, so each
// boundary face joined to p is a positively oriented new tetrahedron (p first, then the face with
// a vertex at infinity last). The new tetrahedra take the cavity's slots first; their faces through
// p are paired by the boundary edge they contain, which the two faces hold in opposite directions
// (a table by directed edge, written in one pass and read in another; sorted edges for large
// cavities).
//
// Partitions (after Marot, Pellerin & Remacle, "One machine, one minute, three billion tetrahedra",
// IJNME 2019, made deterministic). Each pass labels every point with a partition, by rules that
// depend only on the points and the round (never on the thread count): the first pass cuts the
// round's points, in Hilbert order, into P equal ranges of the curve (P from the round's size);
// the later ones cut space into P slabs across oblique directions at quantiles of the points
// still pending (the first pass defers points along its ranges' boundaries, which are made of the
// curve's axis-aligned cells; oblique slabs cross those in lines only, so most of them are inside a
// slab in the next pass). Partition i owns the tetrahedra whose finite corners are all labelled i;
// it walks, grows cavities and writes only there, taking new slots from its own free list and a
// block of slots reserved for it before the pass. A point whose walk or cavity reaches a
// tetrahedron it does not own (or that would overrun the block) is deferred, untouched. Neighbours
// of an owned tetrahedron are owned by the same partition or by none (they share three corners),
// and tetrahedra owned by none are never changed during a pass except for the one face entry that
// a single owner rewrites; so partitions never read what another writes, and each partition's
// work depends only on the mesh at the start of the pass and on its own points. A walk that would
// leave the partition is tried once more from the anchor of the point's cell of the curve (the
// last tetrahedron the partition made for a point there, or one it owns from earlier passes): a
// jump between clusters no longer defers every point after it. What the passes leave is inserted
// serially, as are small rounds and every round after a pass that deferred most of its points
// (cavities reaching across partitions: points on a sphere). The mesh is therefore the same, slot
// for slot, for every thread count and platform.
#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include "delaunay3_internal.hpp"
#include "hull/large_array.hpp"
#include "hull/parallel.hpp"

namespace hullkit {
namespace delaunay3_detail {
namespace {


/// The three corners of a tetrahedron other than k, in increasing order.
constexpr int kOtherThree[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
/// All four, in increasing order (the faces the cavity's first tetrahedron grows across).
constexpr int kAllFour[4] = {0, 1, 2, 3};

/// The lowest bit set in a nonzero 4-bit number.
constexpr std::uint8_t kLowestBit[16] = {0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};

/// kFaceCorners for a ghost (the vertex at infinity is corner 3): the same faces, rotated so that
/// corner 3 comes last (a rotation keeps the orientation).
constexpr int kGhostFaceCorners[4][3] = {{1, 2, 3}, {2, 0, 3}, {0, 1, 3}, {0, 2, 1}};

/// A pass over fewer than 2 x this many points is left to the serial insertion.
constexpr std::size_t kPartitionPoints = 4096;
constexpr std::size_t kMaxPartitions = 8;
constexpr int kMaxPasses = 4;
constexpr std::size_t kCells = 4096;
constexpr std::uint32_t kNoAnchor = 0xffffffffu;

/// What the partitions share: the points and the mesh.
struct Shared {
    Shared(const Points& p, bool furthest_site) : points(p), predicates(p, furthest_site), furthest(furthest_site) {}
    const Points& points;
    Predicates predicates;
    bool furthest;  ///< the furthest-site tetrahedralization: every point lands outside the hull
    Mesh mesh;
    /// Per point, its number + 1 on the boundary of the cavity being linked (0 otherwise; a byte:
    /// Worker::link_small numbers at most kSide of them); each partition numbers only its own
    /// points (a cavity's corners are its own).
    std::vector<std::uint8_t> vertex_id;
    /// Per point, the partition it belongs to in the current pass.
    std::vector<std::uint8_t> part;
    /// In a first pass, where the labels are ranges of local indices: partition i's points are
    /// range[i] ... range[i + 1] - 1 (Worker::owns then compares indices instead of reading labels).
    std::vector<std::uint32_t> range;
    bool ranged = false;
    /// Per cell of the curve (kCells equal ranges of local indices), a tetrahedron made when a
    /// point of that cell was last inserted in a pass (kNoAnchor: none); partitions restart a walk
    /// there (Worker::insert).
    std::vector<std::uint32_t> anchor;
    std::uint32_t cell_shift = 0;  ///< local index >> cell_shift = its cell
};

/// One partition's (or the serial) insertion: its workspace and, in a pass, its label, its anchors,
/// its free slots and its block of fresh slots.
class Worker {
public:
    explicit Worker(Shared& shared) : shared_(shared) {}

    /// Owns everything and appends fresh slots at the end of the mesh (the serial insertion).
    void own_all(std::uint32_t start, std::vector<std::uint32_t>* free_slots) {
        restricted_ = false;
        last_ = start;
        free_ = free_slots;
        block_next_ = block_end_ = 0;
    }
    /// Owns the tetrahedra whose finite corners all carry the label `part` (shared.part), with
    /// these free slots and the fresh slots [block_begin, block_end).
    void own_part(std::uint8_t part, std::uint32_t start, std::vector<std::uint32_t>* free_slots,
                  std::uint32_t block_begin, std::uint32_t block_end) {
        restricted_ = true;
        part_ = part;
        ranged_ = shared_.ranged;
        if (ranged_) first_ = shared_.range[part], count_ = shared_.range[part + 1u] - first_;
        last_ = start;
        free_ = free_slots;
        block_next_ = block_begin;
        block_end_ = block_end;
    }
    bool owns(std::uint32_t t) const {
        const std::uint32_t* c = shared_.mesh.corners(t);
        // The vertex at infinity belongs to everyone: a ghost asks its corner 0 twice.
        const std::uint32_t last = c[3] == kGhost ? c[0] : c[3];
        if (ranged_) {
            return ((c[0] - first_ < count_) & (c[1] - first_ < count_) & (c[2] - first_ < count_) &
                    (last - first_ < count_)) != 0;
        }
        const std::uint8_t* label = shared_.part.data();
        return ((label[c[0]] == part_) & (label[c[1]] == part_) & (label[c[2]] == part_) & (label[last] == part_)) != 0;
    }
    /// Fresh slots of the block not used (returned to the shared free list after a pass).
    std::uint32_t block_next() const { return block_next_; }
    std::uint32_t block_end() const { return block_end_; }
    std::uint32_t last() const { return last_; }

    /// Inserts p; false when p must be deferred (nothing was changed).
    bool insert(std::uint32_t p) {
        const std::uint32_t cell = p >> shared_.cell_shift;
        std::uint32_t t0 = walk(p);
        if (t0 == kDefer) {
            // The walk from the last new tetrahedron left the partition (a jump along the curve
            // between clusters, or across a slab): once more from the anchor of p's cell, a
            // tetrahedron of this partition made for a point near p, when there is one.
            const std::uint32_t a = anchor_[cell];
            if (a == kNoAnchor || a == last_ || shared_.mesh.corners(a)[3] == kFree) return false;
            last_ = a;
            t0 = walk(p);
            if (t0 == kDefer) return false;
        }
        if (!grow_cavity(t0, p)) return false;
        if (!fill_cavity(p)) return false;
        if (restricted_) seed_anchor(cell, last_);
        return true;
    }

    /// Forgets the anchors (before a pass).
    void reset_anchors() {
        if (anchor_.empty()) anchor_.assign(kCells, kNoAnchor);
        for (const std::uint32_t cell : anchored_) anchor_[cell] = kNoAnchor;
        anchored_.clear();
    }
    /// Sets `t` as the anchor of `cell` (a tetrahedron this partition owns): seeded before a pass,
    /// and each new point's last tetrahedron during it.
    void seed_anchor(std::uint32_t cell, std::uint32_t t) {
        if (anchor_[cell] == kNoAnchor) anchored_.push_back(cell);
        anchor_[cell] = t;
    }
    /// The anchors set in this pass, for Shared::anchor afterwards.
    const std::vector<std::uint32_t>& anchored() const { return anchored_; }
    std::uint32_t anchor(std::uint32_t cell) const { return anchor_[cell]; }

    /// A tetrahedron that conflicts with p: one holding it, or a ghost whose hull face p sees;
    /// kDefer when the walk would leave the owned tetrahedra.
    std::uint32_t walk(std::uint32_t p) {
        const std::uint32_t* words = shared_.mesh.data();
        std::uint32_t t = last_;
        if (words[kRow * t + 3] == kGhost) {
            t = words[link_of(t, 3)] >> 3;  // the finite side of its hull face
            if (restricted_ && !owns(t)) return kDefer;
        }
        const Predicates& predicates = shared_.predicates;
        const double* q = predicates.p(p);
        const double bound = predicates.orient_bound();
        const bool exact_in_doubles = predicates.exact_in_doubles();
        std::uint32_t entered = 4;  // the face we came in by
        for (;;) {
            const std::uint32_t* c = words + kRow * t;
            // The orientation with corner k replaced by p, for all four k at once and without a
            // branch (which face the walk leaves by is a coin toss: branches on it were
            // mispredicted half the time): the determinant of the other three corners relative to
            // p, signed (k = 0: +[1 2 3], 1: -[0 2 3], 2: +[0 1 3], 3: -[0 1 2]), each expanded by
            // its z column from the six 2x2 minors of the x, y columns, which the four share.
            // Every face decided by orient3d's static bound (a determinant of three differences
            // of the points, whatever its order of expansion) has the exact sign, so the walk
            // takes the same faces as one evaluation by one.
            double x[4], y[4], z[4];
            for (int i = 0; i < 4; ++i) {
                const double* v = predicates.p(c[i]);
                x[i] = v[0] - q[0], y[i] = v[1] - q[1], z[i] = v[2] - q[2];
            }
            const double m01 = x[0] * y[1] - x[1] * y[0], m02 = x[0] * y[2] - x[2] * y[0];
            const double m03 = x[0] * y[3] - x[3] * y[0], m12 = x[1] * y[2] - x[2] * y[1];
            const double m13 = x[1] * y[3] - x[3] * y[1], m23 = x[2] * y[3] - x[3] * y[2];
            const double det[4] = {(z[1] * m23 - z[2] * m13) + z[3] * m12, -((z[0] * m23 - z[2] * m03) + z[3] * m02),
                                   (z[0] * m13 - z[1] * m03) + z[3] * m01, -((z[0] * m12 - z[1] * m02) + z[2] * m01)};
            // Faces beyond which p lies for certain, and faces the bound cannot decide (none when
            // the values are exact: 0 is not beyond); never back across the face we came in by.
            const std::uint32_t open = 15u & ~(1u << entered);
            std::uint32_t beyond = 0, unsure = 0;
            for (std::uint32_t k = 0; k < 4; ++k) {
                beyond |= static_cast<std::uint32_t>(det[k] < -bound) << k;
                unsure |= static_cast<std::uint32_t>(!(det[k] < -bound) & !(det[k] > bound)) << k;
            }
            beyond &= open;
            unsure &= exact_in_doubles ? 0u : open;
            // The first face beyond, in the order first, first + 1, ... (mod 4).
            const std::uint32_t first = next_random() & 3u;
            std::uint32_t exit = 4;
            if (unsure == 0) {
                const std::uint32_t rotated = ((beyond | beyond << 4) >> first) & 15u;
                if (rotated != 0) exit = (first + kLowestBit[rotated]) & 3u;
            } else {
                for (std::uint32_t i = 0; i < 4 && exit == 4; ++i) {
                    const std::uint32_t k = (first + i) & 3u;
                    bool out = (beyond >> k) & 1u;
                    if (!out && ((unsure >> k) & 1u)) {
                        std::uint32_t w[4] = {c[0], c[1], c[2], c[3]};
                        w[k] = p;
                        out = orient3d(predicates.p(w[0]), predicates.p(w[1]), predicates.p(w[2]), predicates.p(w[3])) < 0;
                    }
                    if (out) exit = k;
                }
            }
            if (exit == 4) return t;
            const std::uint32_t next = words[link_of(t, exit)];
            t = next >> 3;
            entered = next & 3u;
            if (restricted_ && !owns(t)) return kDefer;
            if (words[kRow * t + 3] == kGhost) return t;
        }
    }

private:
    static constexpr std::uint32_t kDefer = 0xffffffffu;

    std::uint32_t next_random() {
        random_ ^= random_ << 13;
        random_ ^= random_ >> 17;
        random_ ^= random_ << 5;
        return random_;
    }

    // While a cavity grows, its tetrahedra are marked in the top bits of their first corner (a
    // point index, below 2^30; the vertex at infinity is always the last corner). The mark is read
    // with the row the conflict test reads anyway, and costs no array of its own. Only the worker
    // that owns a tetrahedron marks it, and workers read only the rows of tetrahedra they own or
    // that no partition owns. A neighbour found not in conflict is not marked: the few met twice
    // (3 a point among 24) are tested twice, which costs less than marking and unmarking them all.
    static constexpr std::uint32_t kInCavity = 1u << 30, kIndex = kInCavity - 1;

    void unmark() {
        std::uint32_t* words = shared_.mesh.data();
        for (const std::uint32_t t : cavity_) words[kRow * t] &= kIndex;
    }

    /// Collects the cavity (marked kInCavity) from t0 and its boundary faces, each with the other
    /// corners of its new tetrahedron (after p) and the neighbour outside.
    /// False (marks undone) when the cavity reaches a tetrahedron this worker does not own.
    /// (Two versions, AVX2 and baseline: the in-sphere tests inline here are most of its work.)
    HULLKIT_AVX2_CLONE bool grow_cavity(std::uint32_t t0, std::uint32_t p) {
        std::uint32_t* words = shared_.mesh.data();
        cavity_.clear();
        entered_.clear();
        boundary_.clear();
        words[kRow * t0] |= kInCavity;
        cavity_.push_back(t0);
        entered_.push_back(4);
        // The neighbours' rows are fetched ahead, as soon as a tetrahedron joins the cavity (its
        // row, holding the links, has just been read): the mesh is too large for the caches, and
        // these misses were a fifth of the time.
        auto fetch_neighbours = [&](std::uint32_t t) {
            const std::uint32_t* links = words + kRow * t + 4;
            for (std::uint32_t k = 0; k < 4; ++k) __builtin_prefetch(words + kRow * (links[k] >> 3));
        };
        fetch_neighbours(t0);
        for (std::size_t i = 0; i < cavity_.size(); ++i) {
            const std::uint32_t t = cavity_[i];
            const std::uint32_t* next = words + kRow * t + 4;
            // Not back across the face it was reached by (its neighbour there is in the cavity):
            // the other three in increasing order (kOtherThree), all four for t0.
            const std::uint8_t entered = entered_[i];
            const int* faces = entered == 4 ? kAllFour : kOtherThree[entered];
            const std::uint32_t count = entered == 4 ? 4 : 3;
            for (std::uint32_t j = 0; j < count; ++j) {
                const std::uint32_t k = static_cast<std::uint32_t>(faces[j]);
                const std::uint32_t across = next[k];
                const std::uint32_t u = across >> 3;
                // A neighbour of an owned tetrahedron is owned by this worker or by none, and only
                // its owner ever marks it: its mark can be read before its ownership is known, and
                // its conflict tested (reading only its row and points). Its ownership matters only
                // in conflict (most neighbours are not): one owned by no partition is never marked
                // (another partition may look at it) and would have to change, so p waits for a
                // later pass.
                if (words[kRow * u] & kInCavity) continue;
                if (shared_.predicates.conflict(words + kRow * u, p)) {
                    if (restricted_ && !owns(u)) {
                        unmark();
                        return false;
                    }
                    words[kRow * u] |= kInCavity;
                    fetch_neighbours(u);
                    cavity_.push_back(u);
                    entered_.push_back(static_cast<std::uint8_t>(across & 3u));
                    continue;
                }
                // The face, counter-clockwise seen from outside the cavity, a ghost's vertex at
                // infinity last: p and these three make the new tetrahedron, positively oriented.
                const std::uint32_t* c = words + kRow * t;
                const int* f = c[3] == kGhost ? kGhostFaceCorners[k] : kFaceCorners[k];
                const std::uint32_t v0 = c[f[0]], v1 = c[f[1]], v2 = c[f[2]];
                boundary_.push_back({{v0 & kIndex, v1 & kIndex, v2}, across});
            }
        }
        return true;
    }

    /// Replaces the cavity by its boundary faces joined to the point p. False (marks undone,
    /// nothing changed) when the block of fresh slots would run out.
    bool fill_cavity(std::uint32_t p) {
        const std::size_t count = boundary_.size();
        const std::size_t reused = std::min(count, cavity_.size());
        const std::size_t from_free = std::min(count - reused, free_->size());
        const std::size_t fresh = count - reused - from_free;
        if (restricted_ && fresh > block_end_ - block_next_) {
            unmark();
            return false;
        }
        slots_.assign(cavity_.begin(), cavity_.begin() + reused);
        for (std::size_t i = 0; i < from_free; ++i) {
            slots_.push_back(free_->back());
            free_->pop_back();
        }
        if (restricted_) {
            for (std::size_t i = 0; i < fresh; ++i) slots_.push_back(block_next_++);
        } else if (fresh > 0) {
            const std::size_t first = shared_.mesh.size();
            grow(first + fresh);
            for (std::size_t i = 0; i < fresh; ++i) slots_.push_back(static_cast<std::uint32_t>(first + i));
        }
        // The cavity's rows that are reused are written whole below (their marks with them); those
        // left over (a cavity with more cells than faces) become free, their marks cleared.
        for (std::size_t i = count; i < cavity_.size(); ++i) {
            std::uint32_t* row = shared_.mesh.data() + kRow * cavity_[i];
            row[0] &= kIndex;
            row[3] = kFree;
            free_->push_back(cavity_[i]);
        }

        std::uint32_t* words = shared_.mesh.data();
        // Each new tetrahedron is p, v0, v1, v2: face 0 is the boundary face, and face j (1 to 3)
        // holds p and the boundary edge from v[j mod 3] to v[(j + 1) mod 3], which the new
        // tetrahedron across it has the other way round (the boundary is a closed surface whose
        // faces all turn the same way).
        for (std::size_t i = 0; i < count; ++i) {
            const Boundary& b = boundary_[i];
            const std::uint32_t n = slots_[i];
            std::uint32_t* row = words + kRow * n;
            row[0] = p;
            std::memcpy(row + 1, b.v, sizeof b.v);
            row[4] = b.outside;
            words[b.outside] = link_of(n, 0);
        }
        if (count <= kSmallBoundary) {
            link_small(words, count);
        } else {
            link_large(words, count);
        }
        last_ = slots_[0];
        for (std::size_t i = 0; i < count; ++i)
            if (boundary_[i].v[2] != kGhost) {
                last_ = slots_[i];
                break;
            }
        return true;
    }

    /// Links the new tetrahedra's faces through p (a boundary of at most kSmallBoundary faces, so
    /// at most kSide vertices): the boundary's vertices numbered 0, 1, ... (per-point slots,
    /// cleared afterwards), each directed edge's face written into a kSide x kSide table, then each
    /// face reads the entry of its edge the other way round. No branch on the data: whether a vertex
    /// was met before goes either way at random, and mispredicted branches were most of the cost.
    void link_small(std::uint32_t* words, std::size_t count) {
        // Every array through a local pointer: a byte stored may alias anything, and members would
        // be loaded again after each one.
        const Boundary* boundary = boundary_.data();
        const std::uint32_t* slots = slots_.data();
        std::uint8_t* vertex_id = shared_.vertex_id.data();
        std::uint8_t* ghost_id = &ghost_id_;
        std::uint32_t* numbered = numbered_.data();
        std::uint8_t* local = local_.data();
        std::uint32_t vertices = 0;
        std::size_t listed = 0;
        for (std::size_t i = 0; i < count; ++i) {
            for (int j = 0; j < 3; ++j) {
                const std::uint32_t v = boundary[i].v[j];
                std::uint8_t* id = v == kGhost ? ghost_id : vertex_id + v;
                const std::uint32_t before = *id, fresh = before == 0;
                vertices += fresh;
                const std::uint32_t number = fresh ? vertices : before;
                *id = static_cast<std::uint8_t>(number);
                numbered[listed] = v;
                listed += fresh;
                local[3 * i + j] = static_cast<std::uint8_t>((number - 1) & (kSide - 1));
            }
        }
        for (std::size_t k = 0; k < listed; ++k) {
            const std::uint32_t v = numbered[k];
            *(v == kGhost ? ghost_id : vertex_id + v) = 0;
        }
        // A closed surface of triangles with V vertices has 2V - 4 of them.
        if (2 * std::size_t{vertices} != count + 4) throw std::logic_error("delaunay3: a cavity's boundary is not closed");
        std::uint32_t* table = table_.data();
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint32_t id0 = local[3 * i], id1 = local[3 * i + 1], id2 = local[3 * i + 2];
            const std::uint32_t face = link_of(slots[i], 0);
            table[id1 * kSide + id2] = face + 1;
            table[id2 * kSide + id0] = face + 2;
            table[id0 * kSide + id1] = face + 3;
        }
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint32_t id0 = local[3 * i], id1 = local[3 * i + 1], id2 = local[3 * i + 2];
            const std::uint32_t face = link_of(slots[i], 0);
            const std::uint32_t across1 = table[id2 * kSide + id1], across2 = table[id0 * kSide + id2];
            const std::uint32_t across3 = table[id1 * kSide + id0];
            words[face + 1] = across1;
            words[face + 2] = across2;
            words[face + 3] = across3;
        }
        // Every face's neighbour names it back (an entry left from an earlier cavity would not).
        bool paired = true;
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint32_t face = link_of(slots[i], 0);
            for (std::uint32_t j = 1; j < 4; ++j) paired &= words[words[face + j]] == face + j;
        }
        if (!paired) throw std::logic_error("delaunay3: a cavity's boundary is not closed");
    }

    /// The same for a larger boundary (points on a sphere and its centre: a cavity of every
    /// tetrahedron): the directed edges sorted by their two ends, each undirected edge met twice.
    void link_large(std::uint32_t* words, std::size_t count) {
        edges_.clear();
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint32_t* v = boundary_[i].v;
            const std::uint32_t face = link_of(slots_[i], 0);
            for (std::uint32_t j = 0; j < 3; ++j) {
                const std::uint32_t a = v[(j + 1) % 3], b = v[(j + 2) % 3];
                edges_.push_back({(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b), face + 1 + j});
            }
        }
        std::sort(edges_.begin(), edges_.end(), [](const Edge& x, const Edge& y) {
            return x.key < y.key || (x.key == y.key && x.face < y.face);
        });
        for (std::size_t e = 0; e < edges_.size(); e += 2) {
            if (e + 1 == edges_.size() || edges_[e].key != edges_[e + 1].key ||
                (e + 2 < edges_.size() && edges_[e + 2].key == edges_[e].key))
                throw std::logic_error("delaunay3: a cavity's boundary is not closed");
            words[edges_[e].face] = edges_[e + 1].face;
            words[edges_[e + 1].face] = edges_[e].face;
        }
    }

    void grow(std::size_t tetrahedra) {
        Mesh& mesh = shared_.mesh;
        if (tetrahedra > kMaxTetrahedra) throw std::length_error("more than 2^29 tetrahedra");
        if (kRow * tetrahedra > mesh.words.capacity()) {
            // Beyond the estimate (rare: non-uniform inputs): grow by half again.
            mesh.words.reserve(kRow * (tetrahedra + tetrahedra / 2));
        }
        mesh.words.resize(kRow * tetrahedra);
    }

    struct Boundary {
        std::uint32_t v[3];    ///< the new tetrahedron's corners after p (a vertex at infinity last)
        std::uint32_t outside; ///< the neighbour across the face, as 4 * tetrahedron + its face
    };
    struct Edge {
        std::uint64_t key;  ///< the edge's ends, lower first
        std::uint32_t face;
    };
    /// Boundaries of at most this many faces are linked through the table (kSide vertices).
    static constexpr std::size_t kSmallBoundary = 124;
    static constexpr std::uint32_t kSide = 64;

    Shared& shared_;
    bool restricted_ = false;
    std::uint8_t part_ = 0;
    bool ranged_ = false;
    std::uint32_t first_ = 0, count_ = 0;  ///< with ranged_: the local indices owned
    std::uint32_t last_ = 0;
    std::vector<std::uint32_t>* free_ = nullptr;
    std::uint32_t block_next_ = 0, block_end_ = 0;
    std::vector<std::uint32_t> cavity_, slots_;
    /// Per cavity tetrahedron, the face it was reached by (4 for the first): that neighbour is in
    /// the cavity already, so growth skips it without reading its mark (a mispredicted branch in
    /// a third of the cases otherwise).
    std::vector<std::uint8_t> entered_;
    std::vector<Boundary> boundary_;
    std::vector<std::uint32_t> table_ = std::vector<std::uint32_t>(kSide * kSide, 0);  ///< faces by directed edge
    std::vector<std::uint32_t> numbered_ = std::vector<std::uint32_t>(3 * kSmallBoundary + 1);  ///< the vertices numbered
    std::vector<std::uint8_t> local_ = std::vector<std::uint8_t>(3 * kSmallBoundary);  ///< their numbers per face
    std::vector<Edge> edges_;
    std::uint8_t ghost_id_ = 0;
    std::uint32_t random_ = 0x9e3779b9u;
    /// Per cell, the tetrahedron this partition last made for a point there in this pass (or
    /// seeded from Shared::anchor), each a slot only this partition writes during the pass;
    /// `anchored_` lists the cells set.
    std::vector<std::uint32_t> anchor_, anchored_;
};

/// The first tetrahedron from the first four affinely independent points in insertion order and
/// its four ghosts; returns the positions in points.order of the four points used.
std::array<std::size_t, 4> start_mesh(Shared& shared) {
    const auto& order = shared.points.order;
    const Predicates& predicates = shared.predicates;
    const std::size_t m = order.size();
    std::size_t c = 2;
    while (c < m && collinear3d(predicates.p(order[0]), predicates.p(order[1]), predicates.p(order[c]))) ++c;
    std::size_t d = c + 1;
    while (d < m && predicates.orient(order[0], order[1], order[c], order[d]) == 0) ++d;
    if (d >= m) throw std::logic_error("delaunay3: the points are coplanar");
    std::uint32_t v[4] = {order[0], order[1], order[c], order[d]};
    if (predicates.orient(v[0], v[1], v[2], v[3]) < 0) std::swap(v[0], v[1]);
    std::uint32_t corners[5][4];
    std::copy(v, v + 4, corners[0]);
    for (int k = 0; k < 4; ++k) {
        for (int i = 0; i < 3; ++i) corners[k + 1][i] = v[kFaceCorners[k][i]];
        corners[k + 1][3] = kGhost;
    }
    Mesh& mesh = shared.mesh;
    const std::size_t expected = 7 * m + 64;  // ~6.7 per point for uniform points
    detail::reserve_large(mesh.words, kRow * expected);
    mesh.words.resize(kRow * 5);
    shared.vertex_id.assign(m, 0);
    shared.part.assign(m, 0);
    shared.anchor.assign(kCells, kNoAnchor);
    while ((m >> shared.cell_shift) >= kCells) ++shared.cell_shift;
    for (int t = 0; t < 5; ++t) std::copy(corners[t], corners[t] + 4, mesh.data() + kRow * t);
    // Pair the five tetrahedra's faces by their corner sets (20 faces: a direct search).
    auto face_set = [&](int t, int k) {
        std::array<std::uint32_t, 3> f{};
        for (int i = 0, n = 0; i < 4; ++i)
            if (i != k) f[n++] = corners[t][i];
        std::sort(f.begin(), f.end());
        return f;
    };
    for (int t = 0; t < 5; ++t)
        for (int k = 0; k < 4; ++k)
            for (int u = 0; u < 5; ++u)
                for (int j = 0; j < 4; ++j)
                    if (u != t && face_set(t, k) == face_set(u, j)) mesh.data()[link_of(t, k)] = link_of(u, j);
    return {0, 1, c, d};
}

/// Inserts one round's points (in curve order) in partitions, as described at the top.
class Rounds {
public:
    Rounds(Shared& shared, unsigned threads) : shared_(shared), threads_(threads), serial_(shared) {
        for (std::size_t i = 0; i <= kMaxPartitions; ++i) workers_.emplace_back(shared);
        if (threads_ > 1) {
            // The mesh's rows mapped on the threads now, rather than page by page on the calling
            // thread as the serial resizes first touch them (a tenth of a 2-thread run): as many
            // as uniform points make (6.77 a point; the room reserved beyond stays unmapped
            // until used, so that it costs no memory).
            Mesh& mesh = shared_.mesh;
            const std::size_t rows_expected = 27 * shared_.points.size() / 4 + 64;
            const std::size_t words = std::min(mesh.words.capacity(), kRow * rows_expected);
            const detail::Prefault rows{mesh.words.data(), words * sizeof(std::int32_t), 32};
            detail::parallel_for(threads_, 32, [&](std::size_t k) { rows.part(k); });
        }
    }

    void insert_round(std::vector<std::uint32_t> pending) {
        const std::size_t all = pending.size();
        // Larger partitions defer fewer points (their boundary layer is a smaller share): 2 parts
        // below 2^17 points, 4 below 2^20, then 8. Never the thread count.
        const std::size_t parts = all < (std::size_t{1} << 17) ? 2 : all < (std::size_t{1} << 20) ? 4 : 8;
        for (int pass = 0; pass < kMaxPasses && !serial_only_ && pending.size() >= 2 * kPartitionPoints; ++pass) {
            label_points(pending, parts, pass);
            const std::size_t before = pending.size();
            pending = pass_over(std::move(pending), parts);
            // Cavities that reach across the partitions (points on or near a sphere, where every
            // circumsphere is nearly the sphere itself) defer almost every point: from then on
            // the partitions would only cost time, so the rest is inserted serially. (Counts
            // only: the same decision for every thread count.)
            if (pending.size() > before - before / 4) serial_only_ = true;
        }
        serial_.own_all(last_, &free_);
        for (const std::uint32_t p : pending) {
            const bool inserted = serial_.insert(p);
            (void)inserted;  // the serial worker owns everything: it never defers
        }
        last_ = serial_.last();
    }

private:
    /// Labels every point with its partition for this pass (shared.part). The first pass cuts the
    /// pending points (in curve order) into `parts` equal ranges of the curve. The points it defers
    /// lie along the boundaries of those ranges, which are made of axis-aligned squares (the
    /// curve's cells), so later passes cut space into slabs across an oblique direction instead
    /// (x + y + z, then x - y + z, then x + y - z; sums only, the same roundings everywhere) at
    /// quantiles of the pending points: the new boundaries cross the old ones in lines only.
    void label_points(const std::vector<std::uint32_t>& pending, std::size_t parts, int pass) {
        std::uint8_t* label = shared_.part.data();
        const std::size_t m = shared_.part.size();
        shared_.ranged = pass == 0;
        if (pass == 0) {
            std::size_t from = 0;
            shared_.range.assign(1, 0);
            for (std::size_t i = 0; i < parts; ++i) {
                const std::size_t to = i + 1 == parts ? m : pending[(i + 1) * pending.size() / parts];
                std::fill(label + from, label + std::max(from, to), static_cast<std::uint8_t>(i));
                from = std::max(from, to);
                shared_.range.push_back(static_cast<std::uint32_t>(from));
            }
            return;
        }
        // (Products by +-1 are exact: fused or not, the same keys.)
        const double sign_y = pass == 2 ? -1.0 : 1.0, sign_z = pass == 3 ? -1.0 : 1.0;
        const Predicates& predicates = shared_.predicates;
        auto key = [&](std::uint32_t v) {
            const double* q = predicates.p(v);
            return q[0] + sign_y * q[1] + sign_z * q[2];
        };
        std::vector<double> keys(pending.size());
        for (std::size_t k = 0; k < pending.size(); ++k) keys[k] = key(pending[k]);
        std::sort(keys.begin(), keys.end());
        double cuts[kMaxPartitions];
        for (std::size_t i = 1; i < parts; ++i) cuts[i - 1] = keys[i * keys.size() / parts];
        constexpr std::size_t kBlock = std::size_t{1} << 16;
        detail::parallel_for(threads_, (m + kBlock - 1) / kBlock, [&](std::size_t block) {
            for (std::size_t v = block * kBlock; v < std::min(m, (block + 1) * kBlock); ++v) {
                const double k = key(static_cast<std::uint32_t>(v));
                std::uint8_t part = 0;
                for (std::size_t i = 0; i + 1 < parts; ++i) part += cuts[i] <= k;
                label[v] = part;
            }
        });
    }

    /// One parallel pass over `pending` (in curve order) with the partitions labelled in
    /// shared.part; returns the deferred points, in curve order.
    std::vector<std::uint32_t> pass_over(std::vector<std::uint32_t> pending, std::size_t parts) {
        std::vector<std::vector<std::uint32_t>> lists(parts);
        {
            std::vector<std::size_t> sizes(parts, 0);  // each list reserved whole: no copies as they grow
            for (const std::uint32_t p : pending) ++sizes[shared_.part[p]];
            for (std::size_t i = 0; i < parts; ++i) lists[i].reserve(sizes[i]);
        }
        for (const std::uint32_t p : pending) lists[shared_.part[p]].push_back(p);
        pending = std::vector<std::uint32_t>();  // the lists hold them now
        // Starting tetrahedra (serially): the one holding a point of the partition's list that it
        // owns, trying positions 0, 1, 3, 7, 15, ... (the list's first points lie at the range's
        // boundary, where tetrahedra often have corners in the next range). The points before the
        // one found wait for the next pass.
        std::vector<std::uint32_t> start(parts, kNoStart);
        std::vector<std::size_t> first(parts, 0);
        serial_.own_all(last_, &free_);
        for (std::size_t i = 0; i < parts; ++i) {
            workers_[i].own_part(static_cast<std::uint8_t>(i), 0, nullptr, 0, 0);
            for (std::size_t k = 0; k < lists[i].size() && start[i] == kNoStart; k = 2 * k + 1) {
                // A ghost (the walk of a point outside the hull: every point of a furthest-site
                // tetrahedralization, most points on a sphere) starts one when the finite side of
                // its hull face is owned too: the partition's walks begin there.
                const std::uint32_t t = serial_.walk(lists[i][k]);
                const std::uint32_t* row = shared_.mesh.corners(t);
                const bool ghost = row[3] == kGhost;
                if (workers_[i].owns(t) && (!ghost || workers_[i].owns(row[4 + 3] >> 3))) {
                    start[i] = t;
                    first[i] = k;
                }
            }
        }
        // Each partition starts with the anchors (of earlier passes) that are finite tetrahedra it owns.
        for (std::size_t i = 0; i < parts; ++i) workers_[i].reset_anchors();
        for (std::uint32_t cell = 0; cell < kCells; ++cell) {
            const std::uint32_t t = shared_.anchor[cell];
            if (t == kNoAnchor || shared_.mesh.corners(t)[3] >= kFree) continue;  // ghost or free
            const std::uint8_t owner = shared_.part[shared_.mesh.corners(t)[0]];
            if (owner < parts && workers_[owner].owns(t)) workers_[owner].seed_anchor(cell, t);
        }
        // Free slots shared out in order, then a block of fresh slots each.
        std::vector<std::vector<std::uint32_t>> free(parts);
        std::vector<std::uint32_t> block_begin(parts), block_end(parts);
        {
            std::size_t taken = 0;
            std::size_t size = shared_.mesh.size();
            for (std::size_t i = 0; i < parts; ++i) {
                // (6.75 a point: uniform points make 6.77 tetrahedra each, and deferred ones
                // none here; slots left over are wasted if no later pass takes them.)
                const std::size_t want = 27 * lists[i].size() / 4 + 256;
                const std::size_t share = std::min(want, free_.size() - taken);
                free[i].assign(free_.begin() + taken, free_.begin() + taken + share);
                taken += share;
                block_begin[i] = static_cast<std::uint32_t>(size);
                size += want - share;
                block_end[i] = static_cast<std::uint32_t>(size);
            }
            free_.erase(free_.begin(), free_.begin() + taken);
            grow_blocks(size);
        }
        std::vector<std::vector<std::uint32_t>> deferred(parts);
        std::vector<std::uint32_t> lasts(parts, kNoStart);
        detail::parallel_for(threads_, parts, [&](std::size_t i) {
            if (start[i] == kNoStart) {
                deferred[i] = lists[i];
                return;
            }
            Worker& w = workers_[i];
            w.own_part(static_cast<std::uint8_t>(i), start[i], &free[i], block_begin[i], block_end[i]);
            const std::vector<std::uint32_t>& list = lists[i];
            deferred[i].assign(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(first[i]));
            for (std::size_t k = first[i]; k < list.size(); ++k)
                if (!w.insert(list[k])) deferred[i].push_back(list[k]);
            lasts[i] = w.last();
        });
        for (std::size_t i = 0; i < parts; ++i)
            for (const std::uint32_t cell : workers_[i].anchored()) shared_.anchor[cell] = workers_[i].anchor(cell);
        // Unused slots back to the shared free list, in partition order.
        std::vector<std::uint32_t> next;
        for (std::size_t i = 0; i < parts; ++i) {
            free_.insert(free_.end(), free[i].begin(), free[i].end());
            const std::uint32_t from = start[i] == kNoStart ? block_begin[i] : workers_[i].block_next();
            for (std::uint32_t s = from; s < block_end[i]; ++s) {
                shared_.mesh.data()[kRow * s + 3] = kFree;
                free_.push_back(s);
            }
            next.insert(next.end(), deferred[i].begin(), deferred[i].end());
            if (lasts[i] != kNoStart) last_ = lasts[i];
        }
        std::sort(next.begin(), next.end());  // slabs list their points slab by slab
        return next;
    }

    /// Room for `slots` tetrahedra (the partitions' blocks: each slot is written when taken, and
    /// those left are marked free after the pass).
    void grow_blocks(std::size_t slots) {
        Mesh& mesh = shared_.mesh;
        if (slots > kMaxTetrahedra) throw std::length_error("more than 2^29 tetrahedra");
        if (kRow * slots > mesh.words.capacity()) mesh.words.reserve(kRow * (slots + slots / 2));
        mesh.words.resize(kRow * slots);
    }

    static constexpr std::uint32_t kNoStart = 0xffffffffu;

    Shared& shared_;
    unsigned threads_;
    Worker serial_;
    std::vector<Worker> workers_;
    std::vector<std::uint32_t> free_;  ///< free slots, shared between passes
    std::uint32_t last_ = 0;
    bool serial_only_ = false;  ///< a pass deferred most of its points: no more partitions
};

}  // namespace

Mesh tetrahedralize(const Points& points, unsigned threads,
                    const std::function<void(std::size_t, std::size_t)>& progress, bool furthest) {
    // Point indices below 2^30 leave the top bits of a row's first corner to the cavity's marks;
    // more points would make more than kMaxTetrahedra tetrahedra anyway (at least 3 per point).
    if (points.size() >= (std::size_t{1} << 30)) throw std::length_error("more than 2^30 points");
    Shared shared(points, furthest);
    const std::array<std::size_t, 4> used = start_mesh(shared);
    Rounds rounds(shared, detail::resolve_threads(threads));
    const std::size_t total = points.size();
    std::size_t done = 4;
    for (std::size_t r = 0; r + 1 < points.rounds.size(); ++r) {
        std::vector<std::uint32_t> round;
        round.reserve(points.rounds[r + 1] - points.rounds[r]);  // no copies as it grows (7/8 of the points)
        for (std::size_t i = points.rounds[r]; i < points.rounds[r + 1]; ++i)
            if (i != used[0] && i != used[1] && i != used[2] && i != used[3]) round.push_back(points.order[i]);
        // The round in curve order (local index order): its points were listed so already, but the
        // four starting points may come from anywhere.
        rounds.insert_round(std::move(round));
        done = points.rounds[r + 1];
        if (progress) progress(done, total);
    }
    return std::move(shared.mesh);
}

}  // namespace delaunay3_detail
}  // namespace hullkit
