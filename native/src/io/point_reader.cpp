// PointReader: point files read in batches, text parsed in pieces on threads (point_reader.hpp).
//
// Text (xyz, rbox, OBJ, OFF): the header is read once (point_text.cpp's read_point_text_header);
// then each batch, about batch_bytes of whole lines, is taken in chunks of whole lines that
// threads claim in input order and parse at once (parse_point_piece), each into its own array;
// the arrays are joined in input order. A chunk knows only its own lines: the join numbers them
// (each chunk counts the lines it read) and checks the header's count, so every message names
// the line parse_points names.
// PLY streams through ply.cpp's PlyReader; STL and inputs whose format only all of their bytes
// decide are read whole and given to read_points.
#include "hullkit/point_reader.hpp"

#include "hullkit/mesh_read.hpp"

#include "hull/large_array.hpp"
#include "hull/parallel.hpp"
#include "mesh_read_internal.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <utility>

#include <sys/stat.h>

namespace hullkit {

namespace io {

void ChunkedInput::grow(std::size_t size, std::size_t keep) {
    if (storage_.size >= size) return;
    const std::size_t grown = std::max(size, storage_.size + storage_.size / 2);
    std::unique_ptr<char[]> data(new char[grown]);
    if (keep) std::memcpy(data.get(), storage_.data.get(), keep);
    storage_.data = std::move(data);
    storage_.size = grown;
}

bool ChunkedInput::fill(std::size_t bytes) {
    while (end_ - pos_ < bytes && !at_end_) {
        const std::size_t rest = end_ - pos_;
        // Keep only the unconsumed bytes, moved to the front, so that the buffer stays about
        // one chunk (plus what a caller asked to see at once).
        if (pos_ != 0) {
            std::memmove(storage_.data.get(), storage_.data.get() + pos_, rest);
            pos_ = 0;
            end_ = rest;
        }
        const std::size_t want = std::max(bytes - rest, chunk_);
        grow(rest + want, rest);
        const std::size_t got = std::fread(storage_.data.get() + rest, 1, want, file_);
        data_ = storage_.data.get();
        end_ = rest + got;
        if (got < want) {  // fread stops short only at the end of the file or on an error
            at_end_ = true;
            if (std::ferror(file_)) read_errno_ = errno ? errno : EIO;
        }
    }
    return end_ - pos_ >= bytes;
}

std::string_view ChunkedInput::take(std::size_t length, ByteBuffer* buffer) {
    const std::string_view taken = available().substr(0, length);
    consume(length);
    if (!file_) return taken;
    std::swap(*buffer, storage_);  // `taken` now lies in *buffer
    const std::size_t rest = end_ - pos_;
    grow(rest, 0);
    if (rest) std::memcpy(storage_.data.get(), taken.data() + length, rest);
    data_ = storage_.data.get();
    pos_ = 0;
    end_ = rest;
    return taken;
}

std::string ChunkedInput::take_rest() {
    // Doubling what is asked for keeps reading a large file whole linear.
    while (!at_end_) fill(2 * (end_ - pos_) + 1);
    std::string rest(available());
    consume(rest.size());
    return rest;
}

}  // namespace io

namespace {

/// How much of the start of the input decides the format: detect_mesh_format looks no further
/// than 64 KiB for the first word.
constexpr std::size_t kHeadBytes = std::size_t{1} << 16;
/// Text is read and parsed in chunks of this many bytes: small enough that a chunk is still in
/// the cache when it is parsed right after it was read (which halves the time against parsing
/// 32 MiB batches read at once), large enough that taking one costs nothing in comparison.
constexpr std::size_t kChunk = std::size_t{1} << 20;
/// A batch is cut into at least this many chunks per thread, so that small batches (tests make
/// them so) are still spread over the threads.
constexpr std::size_t kChunksPerThread = 4;
/// A thread is started for every this many bytes of a batch at most: starting one costs about
/// as much as parsing 100 KB.
constexpr std::uint64_t kBytesPerThread = std::uint64_t{64} << 10;

enum class Mode { Text, Ply, Whole, Done };

}  // namespace

struct PointReader::Impl {
    Impl(std::FILE* file, std::string source_name, const PointReaderOptions& reader_options)
        : input(file, chunk_bytes(reader_options)),
          source(std::move(source_name)),
          options(reader_options) {
        struct stat info {};
        if (fstat(fileno(file), &info) == 0 && S_ISREG(info.st_mode)) {
            // From the current position: a caller may have read part of the file already.
            const long at = std::ftell(file);
            size = static_cast<std::uint64_t>(info.st_size) - static_cast<std::uint64_t>(at > 0 ? at : 0);
            size_known = true;
        }
    }
    Impl(std::string_view text, std::string source_name, const PointReaderOptions& reader_options)
        : input(text), source(std::move(source_name)), options(reader_options), size(text.size()), size_known(true) {}

    io::ChunkedInput input;
    std::string source;
    PointReaderOptions options;
    unsigned threads = detail::resolve_threads(options.threads);
    std::uint64_t size = 0;
    bool size_known = false;
    Mode mode = Mode::Done;
    std::string error;
    std::uint64_t handed_out = 0;  ///< points returned by next() / append_next()
    std::uint64_t declared = 0;

    // Text
    io::PointTextHeader header;
    std::uint64_t parsed = 0;     ///< points in the batches parsed so far
    std::size_t line_base = 0;    ///< lines before the input's unconsumed text
    bool text_done = false;       ///< OFF: every vertex read (the rest is faces, which points ignore)
    /// A chunk of a batch: whole lines, parsed on one thread.
    struct Chunk {
        std::string_view text;
        io::ByteBuffer buffer;        ///< holds the text of a file read on several threads
        std::vector<double> points;   ///< its points, when not parsed straight into the batch
        std::size_t start = 0;        ///< where its points go in the batch, in points
        std::uint64_t limit = 0;      ///< the limit it was parsed with
        bool done = false;            ///< parsed (set and read under the lock that hands chunks out)
        bool copied = false;          ///< its points are in place in the batch
        io::PointPiece piece;
    };
    std::vector<Chunk> chunks;
    std::vector<io::ByteBuffer> spare_buffers;  ///< text buffers no chunk holds, for the next ones
    std::uint64_t last_batch_points = 0;        ///< how many points the last batch had
    std::uint64_t bytes_per_point = 6;          ///< the first batch's guess, from the lines seen first
    io::SkippedRecords skipped;                 ///< OBJ records skipped so far, for warnings()
    std::vector<std::string> whole_warnings;    ///< what read_points said of an input read whole

    // PLY, and inputs read whole
    std::unique_ptr<io::PlyReader> ply;
    std::vector<double> whole;

    /// The size of the chunks text is read and parsed in.
    static std::size_t chunk_bytes(const PointReaderOptions& options) {
        const std::size_t spread = kChunksPerThread * detail::resolve_threads(options.threads);
        return std::max<std::size_t>(1, std::min(kChunk, options.batch_bytes / spread));
    }

    bool fail(std::string message) {
        error = std::move(message);
        mode = Mode::Done;
        return false;
    }
    bool fail_read() { return fail(source + ": cannot read: " + std::strerror(input.read_errno())); }

    /// Decides the format from the first bytes (and the name) and reads any header.
    void start() {
        input.fill(kHeadBytes);
        if (input.read_errno()) {
            fail_read();
            return;
        }
        // The format is judged on the bytes as they are, as read_points judges them (a byte-order
        // mark before "ply" or a glTF header makes text); a UTF-8 byte-order mark before text
        // (some editors start text files with one) is not content, and stays part of line 1.
        switch (route(input.available().substr(0, kHeadBytes))) {
            case Mode::Text:
                input.consume(io::bom_length(input.available()));
                start_text(input.available().substr(0, kHeadBytes));
                break;
            case Mode::Ply: start_ply(); break;
            case Mode::Whole: start_whole(); break;
            case Mode::Done: break;
        }
    }

    /// How read_points would read the input, decided from its first bytes: Text (parse_points),
    /// Ply (read_ply_points), or Whole when only all of its bytes can tell.
    Mode route(std::string_view head) const {
        if (options.text_only) return Mode::Text;
        const std::string extension = io::extension_of(source);
        if (extension == "ply") return Mode::Ply;
        if (extension == "stl" || extension == "gltf" || extension == "glb") return Mode::Whole;
        if (extension == "obj" || extension == "off") return Mode::Text;
        // On the first 64 KiB detect_mesh_format decides as on the whole input, except that it
        // wants no NUL byte anywhere before it takes a first word "solid" for ASCII STL (reading
        // whole lets read_points settle that), and that a binary STL is known by the input's size,
        // which is never that of a 64 KiB head (65536 - 84 is no multiple of 50).
        switch (detect_mesh_format(std::string(head), "")) {
            case MeshFormat::Ply: return Mode::Ply;
            case MeshFormat::StlAscii:
            case MeshFormat::StlBinary:
            case MeshFormat::Gltf:
            case MeshFormat::Glb: return Mode::Whole;
            default: break;
        }
        if (size_known) return io::has_binary_stl_size(head, size) ? Mode::Whole : Mode::Text;
        // A stream (a pipe): its size, which makes binary data a binary STL, is known only at its
        // end, so binary data is read whole. (Text that would make a binary STL by its size
        // alone needs bytes 80..83 of text, a size of 7.5 GB or more: streamed as text.)
        return io::binary_input_message(head.substr(0, io::kSniffBytes), 0, false, "").empty() ? Mode::Text
                                                                                                : Mode::Whole;
    }

    // ---- text ----

    void start_text(std::string_view head) {
        const std::string binary =
            io::binary_input_message(head.substr(0, io::kSniffBytes), size, size_known, "a point file");
        if (!binary.empty()) {
            fail(source + ": " + binary);
            return;
        }
        for (;;) {  // the header, from as many whole lines as it takes
            const std::string_view text = input.available();
            const std::size_t newline = text.rfind('\n');
            const std::size_t length = input.at_end() ? text.size() : newline == std::string_view::npos ? 0 : newline + 1;
            std::string message;
            const io::ReadStatus status =
                io::read_point_text_header(text.substr(0, length), input.at_end(), source, &header, &message);
            if (status == io::ReadStatus::Failed) {
                fail(message);
                return;
            }
            if (status == io::ReadStatus::Done) break;
            input.fill(2 * text.size() + 1);
            if (input.read_errno()) {
                fail_read();
                return;
            }
        }
        input.consume(header.body_offset);
        // The line length at the start of the body, to guess how many points the first batch has.
        const std::string_view sample = input.available().substr(0, kHeadBytes);
        bytes_per_point = std::max<std::uint64_t>(
            6, sample.size() / (static_cast<std::uint64_t>(std::count(sample.begin(), sample.end(), '\n')) + 1));
        line_base = header.body_line;
        declared = header.counted ? header.declared : 0;
        mode = Mode::Text;
    }

    /// The length of the next chunk of text: whole lines, about `bytes` of them (a longer line
    /// whole, and all that was read when that is less than twice as much, so that only a partial
    /// line is left over); 0 at the end of the input.
    std::size_t chunk_length(std::size_t bytes) {
        input.fill(bytes);
        for (;;) {
            const std::string_view text = input.available();
            if (input.at_end() && text.size() <= bytes) return text.size();  // the rest, final line end or not
            const std::size_t window = text.size() < 2 * bytes ? text.size() : bytes;
            std::size_t newline = text.substr(0, window).rfind('\n');
            if (newline == std::string_view::npos) newline = text.find('\n', window);  // a longer line
            if (newline != std::string_view::npos) return newline + 1;
            if (input.at_end()) return text.size();
            input.fill(2 * text.size());
        }
    }

    /// Whether the parsed chunk `c` of a batch on several threads (not direct) may hold the point
    /// where a counted header's count runs out, so that the join must parse it again: if the
    /// points before it in the batch, and its own, may reach its limit. Earlier chunks that are
    /// parsed count with their points, those still being parsed with the most their text could
    /// hold: first a point line takes 6 bytes at least ("0 0 0\n"); when that is not enough to
    /// tell (near the end of the count), one line each. Called under the lock.
    bool may_cross(const Chunk* c) const {
        if (!header.counted) return false;
        for (bool count_lines : {false, true}) {
            std::uint64_t most = c->piece.points;
            for (const Chunk* before = chunks.data(); before != c; ++before) {
                const std::string_view text = before->text;
                most += before->done ? before->piece.points
                        : count_lines ? static_cast<std::uint64_t>(std::count(text.begin(), text.end(), '\n')) + 1
                                      : text.size() / 6;
            }
            if (most < c->limit) return false;
        }
        return true;
    }

    /// What the threads of one batch share; `lock` guards all of it but the atomics.
    struct BatchState {
        std::mutex lock;
        std::size_t claimed = 0;          ///< chunks taken so far
        std::size_t taken = 0;            ///< their bytes
        std::size_t placed = 0;           ///< chunks [0, placed) have their final place in the batch
        std::uint64_t placed_points = 0;  ///< the points of those chunks
        std::size_t room = 0;             ///< points *out holds for the batch, to copy placed chunks into
        std::atomic<bool> stop{false};    ///< set after an error or the last OFF vertex
        std::atomic<bool> make_room{false};  ///< the first thread in is to make more room
    };

    /// Takes the next chunk of the batch (under the lock); null when the batch is full or the
    /// input ends.
    Chunk* claim(BatchState& state, std::size_t batch, std::size_t chunk, std::size_t tasks, bool direct,
                 std::uint64_t limit, const std::vector<double>& out, std::size_t out_start) {
        if (state.stop.load(std::memory_order_relaxed) || state.taken >= batch || state.claimed == tasks) return nullptr;
        // Near the end of a batch on threads the chunks shrink (to an eighth at least), so that
        // the threads finish it close together: the batch ends when its last chunk is parsed.
        const std::size_t left = batch - state.taken;
        const std::size_t want = direct ? chunk : std::clamp(left / threads, std::max<std::size_t>(chunk / 8, 1), chunk);
        const std::size_t length = chunk_length(want);
        if (length == 0) return nullptr;  // the end of the input
        Chunk* c = &chunks[state.claimed];
        c->piece = io::PointPiece();
        c->done = false;
        c->copied = false;
        if (direct) {
            c->text = input.available().substr(0, length);  // stays put until the next fill
            input.consume(length);
            c->limit = header.counted ? limit - (out.size() - out_start) / 3 : limit;
        } else {
            if (!spare_buffers.empty()) {
                c->buffer = std::move(spare_buffers.back());
                spare_buffers.pop_back();
            }
            c->text = input.take(length, &c->buffer);
            c->points.clear();
            c->limit = limit;
        }
        state.taken += length;
        ++state.claimed;
        return c;
    }

    /// After chunk `c` is parsed (under the lock): hands its text buffer on unless the join may
    /// need it, and moves the frontier of placed chunks as far as the parsed ones allow: a chunk
    /// is placed when every chunk before it is, and it neither failed nor ended the vertices nor
    /// went past the count (those the join settles). Returns the first newly placed chunk; the
    /// caller copies [that, state.placed).
    std::size_t finish_chunk(BatchState& state, Chunk* c) {
        c->done = true;
        if (c->buffer.data && !may_cross(c)) spare_buffers.push_back(std::move(c->buffer));
        const std::size_t first = state.placed;
        while (state.placed < state.claimed) {
            Chunk& next = chunks[state.placed];
            if (!next.done || next.piece.error_line || next.piece.at_limit) break;
            if (header.counted && next.piece.points > next.limit - state.placed_points) break;
            next.start = static_cast<std::size_t>(state.placed_points);
            state.placed_points += next.piece.points;
            ++state.placed;
        }
        return first;
    }

    /// Parses the next batch of point lines into *out: appended, or with `replace` in place of
    /// what *out holds. False once there is nothing more (the end of the input, or an error:
    /// then *out is as it was, or empty with `replace`).
    bool text_batch(std::vector<double>* out, bool replace) {
        if (text_done) return finish_text(out, replace);
        const std::size_t batch = std::max<std::size_t>(options.batch_bytes, 1);
        const std::size_t chunk = chunk_bytes(options);
        // Chunks end at line ends, so a batch takes one more than batch / chunk at most; and no
        // more than the input has.
        std::uint64_t bytes = batch;
        if (size_known) bytes = std::min<std::uint64_t>(bytes, size - input.offset());
        // (With the smaller chunks that end a batch on threads: a few per thread.)
        const std::size_t tail = threads > 1 ? 4 * std::size_t{threads} : 0;
        const std::size_t tasks = static_cast<std::size_t>(
            std::min<std::uint64_t>(batch / chunk + 2 + tail, bytes / std::max<std::size_t>(chunk / 8, 1) + 1));
        const unsigned started = static_cast<unsigned>(std::min<std::uint64_t>(threads, bytes / kBytesPerThread + 1));
        // What the array guesses below go by: the batch of a file of known size; of a stream, what
        // was read so far (a small stream must not make room for a whole batch).
        const std::uint64_t seen = size_known ? bytes : std::min<std::uint64_t>(bytes, input.available().size());
        if (chunks.size() < tasks) chunks.resize(tasks);
        // The points the header still allows: an upper bound for every chunk of the batch (the
        // points of earlier chunks count against it too), exact for the first.
        const std::uint64_t limit = header.counted ? header.declared - parsed : ~std::uint64_t{0};
        // On one thread each chunk is parsed from the input's buffer straight into *out, with the
        // exact limit, before the next is read: nothing is copied, nothing parsed again. With
        // several threads each chunk parses its own text into its own array, which the thread
        // that places it copies into *out (while it is in the cache, as long as *out holds as
        // many points as the last batch had), the join the rest; so it goes when a small batch
        // starts no thread (`started`), so that a reader is the same whatever its batches.
        const bool direct = threads == 1;
        if (direct && replace) out->clear();
        const std::size_t out_start = replace ? 0 : out->size();
        // Address space for as many points as the batch could hold (a point line takes 6 bytes at
        // least; a stream's batch may come to hold more), so that *out is not moved while batches
        // grow; its pages are touched only as points are written. Growing geometrically keeps
        // appending batch after batch linear.
        const std::size_t most = 3 * static_cast<std::size_t>(std::min<std::uint64_t>(limit, seen / 6 + 1));
        if (out->capacity() - out_start < most) out->reserve(std::max(out_start + most, 2 * out->capacity()));
        // The untouched room on huge pages where the system has them: a first touch of each 4 KiB
        // page took as long as parsing the text that fills it (see large_array.hpp).
        detail::advise_huge_pages(out->data() + out->size(), (out->capacity() - out->size()) * sizeof(double));
        BatchState state;
        std::size_t wanted = out->size();
        if (!direct) {
            // Room for as many points as the last batch had (the first: as its text would hold at
            // the line length seen so far), no more than the header still allows, within the
            // capacity reserved: making room never moves the array.
            const std::uint64_t expected = std::min<std::uint64_t>(
                last_batch_points ? last_batch_points : seen / bytes_per_point, limit);
            wanted = out_start + 3 * static_cast<std::size_t>(std::min<std::uint64_t>(expected, (out->capacity() - out_start) / 3));
            state.make_room = out->size() < wanted;
        }
        state.room = (out->size() - out_start) / 3;
        double* const into = out->data() + out_start;  // stays put: the room is within the capacity
        detail::parallel_for(started, tasks, [&](std::size_t) {
            if (state.make_room.exchange(false)) {
                // Zero-filling the room touches its pages for the first time, which costs as much
                // as parsing a few chunks: one thread does it while the others parse. No other
                // thread touches *out until the room is published, under the lock.
                out->resize(wanted);
                std::lock_guard<std::mutex> lock(state.lock);
                state.room = (wanted - out_start) / 3;
            }
            Chunk* c = nullptr;
            {
                // Chunks are read and numbered in input order, whichever thread takes them.
                std::lock_guard<std::mutex> lock(state.lock);
                c = claim(state, batch, chunk, tasks, direct, limit, *out, out_start);
            }
            if (!c) return;
            io::parse_point_piece(c->text, header, c->limit, direct ? out : &c->points, &c->piece);
            // Chunks after an error, or after the last OFF vertex, are not needed.
            if (c->piece.error_line || c->piece.at_limit) state.stop.store(true, std::memory_order_relaxed);
            if (direct) return;
            std::size_t first = 0, last = 0, room = 0;
            {
                std::lock_guard<std::mutex> lock(state.lock);
                first = finish_chunk(state, c);
                last = state.placed;
                room = state.room;
            }
            for (std::size_t i = first; i < last; ++i) {  // disjoint places: no lock needed
                Chunk& placed = chunks[i];
                if (placed.start + placed.piece.points > room) break;
                std::copy(placed.points.begin(), placed.points.end(), into + 3 * placed.start);
                placed.copied = true;
            }
        });
        if (input.read_errno()) {
            out->resize(out_start);
            return fail_read();
        }
        if (state.claimed == 0) {
            out->resize(out_start);  // undo the room made for the batch
            return finish_text(out, replace);
        }

        // Join in input order: the first error wins, and everything before it stands.
        std::uint64_t before = parsed;
        std::size_t line = line_base;
        std::size_t joined = 0;
        for (; joined < state.claimed; ++joined) {
            Chunk& c = chunks[joined];
            if (header.counted) {
                const std::uint64_t remaining = header.declared - before;
                // A chunk that went past the declared count under the looser limit is parsed again
                // with the exact one: rbox then fails on the line after its last point, OFF stops
                // where its vertices end. Either way the join ends with it. (Only on several
                // threads, and never a placed chunk: a direct chunk had the exact limit, and its
                // text is gone.)
                if (c.limit != remaining && (c.piece.points > remaining || (c.piece.points == remaining && c.piece.error_line))) {
                    c.points.clear();
                    c.piece = io::PointPiece();
                    io::parse_point_piece(c.text, header, remaining, &c.points, &c.piece);
                }
            }
            if (c.piece.error_line) {
                out->resize(out_start);
                return fail(io::at_line(source, line + c.piece.error_line,
                                        io::describe_problem(c.piece.error_what,
                                                             c.piece.error_point == io::kNoPoint ? io::kNoPoint : static_cast<std::size_t>(before) + c.piece.error_point,
                                                             c.piece.error_tail)));
            }
            c.start = static_cast<std::size_t>(before - parsed);
            before += c.piece.points;
            skipped.merge(c.piece.skipped, line);
            line += c.piece.lines;
            if (c.piece.at_limit) {
                ++joined;
                break;
            }
        }
        const std::size_t points = static_cast<std::size_t>(before - parsed);
        if (!direct) {
            // The texts kept for parsing again are not needed any more.
            for (std::size_t i = 0; i < state.claimed; ++i) {
                if (chunks[i].buffer.data) spare_buffers.push_back(std::move(chunks[i].buffer));
            }
            out->resize(out_start + 3 * points);
            // The chunks not copied yet (all of them when *out had no room, as for the first
            // batch), on the threads too when that is much: the copy is not left to one thread.
            std::size_t left = 0;
            for (std::size_t i = 0; i < joined; ++i) left += chunks[i].copied ? 0 : chunks[i].points.size();
            double* const batch_start = out->data() + out_start;
            detail::parallel_for(left * sizeof(double) > 4 * kBytesPerThread ? started : 1, joined, [&](std::size_t i) {
                const Chunk& c = chunks[i];
                if (!c.copied) std::copy(c.points.begin(), c.points.end(), batch_start + 3 * c.start);
            });
        }
        if (header.format == io::PointTextFormat::Off && before == header.declared) text_done = true;
        parsed = before;
        line_base = line;
        last_batch_points = points;
        return true;
    }

    /// The end of point text: the header's count must have been met, and there must be points.
    bool finish_text(std::vector<double>* out, bool replace) {
        if (replace) out->clear();
        mode = Mode::Done;
        if (header.counted && parsed < header.declared) {
            return fail(io::at_line(source, header.count_line, io::missing_points_message(header, parsed)));
        }
        return false;  // the end (no points at all is no error: an empty cloud)
    }

    // ---- PLY ----

    // Elements before "vertex", and faces after it, are read and checked row by row as they
    // stream past (face indices need only the vertex count, which the header gives), so no PLY
    // is ever read whole.
    void start_ply() {
        ply = std::make_unique<io::PlyReader>(input, source, /*faces_required=*/false);
        const bool started = ply->start();
        if (input.read_errno()) {
            fail_read();
        } else if (!started) {
            fail(ply->error());
        } else {
            declared = ply->vertex_count();
            mode = Mode::Ply;
        }
    }

    bool ply_batch(std::vector<double>* out) {
        if (ply->done()) {
            mode = Mode::Done;
            return false;
        }
        const std::size_t out_start = out->size();
        const bool ok = ply->read(options.batch_bytes, out, nullptr);
        if (!ok || input.read_errno()) {
            out->resize(out_start);
            return input.read_errno() ? fail_read() : fail(ply->error());
        }
        return true;
    }

    // ---- read whole ----

    void start_whole() {
        const std::string bytes = input.take_rest();
        if (input.read_errno()) {
            fail_read();
            return;
        }
        PointsResult result = read_points(bytes, source);
        if (!result.ok()) {
            fail(std::move(result.error));
            return;
        }
        whole = std::move(result.xyz);
        whole_warnings = std::move(result.warnings);
        mode = Mode::Whole;
    }

    /// The next batch for next() (`replace`) or append_next().
    bool next(std::vector<double>* out, bool replace) {
        // Text replaces in place, without clearing first: with threads, only the growth of the
        // caller's array is then zero-filled before the batch is copied in.
        if (replace && mode != Mode::Text) out->clear();
        const std::size_t start = replace ? 0 : out->size();
        do {  // a batch of only comments (or a PLY's faces) holds no point
            bool more = false;
            switch (mode) {
                case Mode::Text: more = text_batch(out, replace); break;
                case Mode::Ply: more = ply_batch(out); break;
                case Mode::Whole: more = whole_batch(out); break;
                case Mode::Done: break;
            }
            if (!more) return false;
        } while (out->size() == start);
        handed_out += (out->size() - start) / 3;
        return true;
    }

    bool whole_batch(std::vector<double>* out) {
        mode = Mode::Done;
        if (out->empty()) {
            out->swap(whole);
        } else {
            out->insert(out->end(), whole.begin(), whole.end());
        }
        whole = std::vector<double>();
        return true;
    }
};

PointReader::PointReader(std::FILE* file, std::string source, PointReaderOptions options)
    : impl_(std::make_unique<Impl>(file, std::move(source), options)) {
    impl_->start();
}

PointReader::PointReader(std::string_view text, std::string source, PointReaderOptions options)
    : impl_(std::make_unique<Impl>(text, std::move(source), options)) {
    impl_->start();
}

PointReader::~PointReader() = default;
PointReader::PointReader(PointReader&&) noexcept = default;
PointReader& PointReader::operator=(PointReader&&) noexcept = default;

bool PointReader::next(std::vector<double>* xyz) { return impl_->next(xyz, /*replace=*/true); }

bool PointReader::append_next(std::vector<double>* xyz) { return impl_->next(xyz, /*replace=*/false); }

const std::string& PointReader::error() const { return impl_->error; }
std::vector<std::string> PointReader::warnings() const {
    std::vector<std::string> out = impl_->whole_warnings;
    if (impl_->header.column_names_line) {
        out.push_back(io::column_names_warning(impl_->header.column_names_line, impl_->header.column_names));
    }
    for (std::string& message : impl_->skipped.messages("unknown OBJ record")) out.push_back(std::move(message));
    return out;
}
std::uint64_t PointReader::points_read() const { return impl_->handed_out; }
std::uint64_t PointReader::bytes_read() const { return impl_->input.offset(); }
std::uint64_t PointReader::size() const { return impl_->size_known ? impl_->size : 0; }
std::uint64_t PointReader::declared_points() const { return impl_->declared; }

}  // namespace hullkit
