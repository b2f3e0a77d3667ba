#include "app/DocumentWire.hpp"

#include <type_traits>
#include <utility>

#include "essi/wire.hpp"

namespace essi::viewer {

namespace {

// (std::pair is not trivially copyable: its parts are written one after the other)
template <class A, class B>
void put_pairs(WireWriter& out, const std::vector<std::pair<A, B>>& v) {
    out.put_items(v, [&](const std::pair<A, B>& p) { out.put_all(p.first, p.second); });
}

template <class A, class B>
bool get_pairs(WireReader& in, std::vector<std::pair<A, B>>& v) {
    return in.get_items(v, sizeof(A) + sizeof(B), [&](std::pair<A, B>& p) { return in.get_all(p.first, p.second); });
}

bool get_kept(WireReader& in, std::vector<std::pair<std::uint32_t, MotionRecord>>& kept) {
    return in.get_items(kept, sizeof(std::uint32_t) + sizeof(MotionRecord) / 2,
                        [&](auto& k) { return in.get(k.first) && restore_motion_record(in, k.second); });
}

bool get_marks(WireReader& in, std::vector<DiagnosticMark>& marks) {
    return in.get_items(marks, sizeof(std::uint32_t) + sizeof(Point),
                        [&](DiagnosticMark& m) { return in.get_all(m.diagnostic, m.at); });
}

void put_messages(WireWriter& out, const std::vector<Message>& messages) {
    out.put_items(messages, [&](const Message& m) {
        out.put(m.msg);
        out.put_string(m.args.packed());
    });
}

bool get_messages(WireReader& in, std::vector<Message>& messages) {
    std::string packed;
    return in.get_items(messages, sizeof(Msg) + sizeof(std::uint64_t), [&](Message& m) {
        if (!in.get(m.msg) || !in.get_string(packed)) return false;
        m.args = MessageArgs::from_packed(std::move(packed));
        return true;
    });
}

void put_setup(WireWriter& out, const TapeSetup& s) {
    out.put(s.format);
    out.put_string(profile_to_json(s.profile));
    out.put(s.auto_profile);
    out.put_items(s.evidence, [&](const std::string& e) { out.put_string(e); });
    std::vector<Diagnostic> note;
    if (s.note) note.push_back(*s.note);
    save_diagnostics(out, note);
    put_messages(out, s.evidence_messages);
}

bool get_setup(WireReader& in, TapeSetup& s) {
    std::string profile;
    if (!in.get(s.format) || !in.get_string(profile) || !in.get(s.auto_profile) ||
        !in.get_items(s.evidence, sizeof(std::uint64_t), [&](std::string& e) { return in.get_string(e); }))
        return false;
    ProfileResult parsed = parse_profile(profile);
    if (!parsed.profile) return false;
    s.profile = std::move(*parsed.profile);
    std::vector<Diagnostic> note;
    if (!restore_diagnostics(in, note) || note.size() > 1) return false;
    s.note.reset();
    if (!note.empty()) s.note = std::move(note.front());
    return get_messages(in, s.evidence_messages);
}

// A decode's steps: each names the part it reads, so that a failure says which.
class Decoding {
public:
    Decoding(std::string_view wire, WireError& error) : in_(wire), error_(error) {}
    WireReader& in() { return in_; }
    // `ok` for the part `what`: false (and the error) when it failed.
    bool check(bool ok, const char* what) {
        if (!ok) error_ = {what, in_.position()};
        return ok;
    }
    bool at_end() { return check(in_.at_end(), "end (bytes after the last part)"); }

private:
    WireReader in_;
    WireError& error_;
};

void put_chunks(WireWriter& out, const std::vector<ReadChunk>& chunks) {
    out.put<std::uint64_t>(chunks.size());
    for (const ReadChunk& c : chunks) {
        out.put_string(c.reader.checkpoint());
        out.put(c.first_block);
        out.put(c.first_line);
    }
}

bool get_chunks(WireReader& in, Document& d) {
    std::uint64_t n = 0;
    if (!in.get_count(n, sizeof(std::uint64_t) + 2 * sizeof(std::uint32_t))) return false;
    d.chunks.clear();
    d.chunks.reserve(static_cast<std::size_t>(n));
    std::string checkpoint;
    for (std::uint64_t k = 0; k < n; ++k) {
        std::uint32_t first_block = 0, first_line = 0;
        if (!in.get_string(checkpoint) || !in.get(first_block) || !in.get(first_line)) return false;
        std::optional<TapeReader> reader = TapeReader::resume(d.bytes, d.profile, d.setup.format, checkpoint);
        if (!reader) return false;
        d.chunks.push_back({std::move(*reader), first_block, first_line});
    }
    return true;
}

}  // namespace

std::string WireError::message() const {
    return "the reading worker's message is cut short or wrong at byte " + std::to_string(at) + ", in its " + what;
}

std::string encode_setup(const TapeSetup& setup) {
    WireWriter out;
    put_setup(out, setup);
    return out.take();
}

bool decode_setup(std::string_view wire, TapeSetup& setup, WireError& error) {
    Decoding d(wire, error);
    return d.check(get_setup(d.in(), setup), "setup") && d.at_end();
}

std::string encode_document(const Document& d) {
    WireWriter out;
    out.put_string(d.name);
    put_setup(out, d.setup);
    save_diagnostics(out, d.diagnostics);
    save_stats(out, d.stats);
    out.put_vector(d.motions);
    out.put_vector(d.arc_centres);
    d.arc_rank.save(out);
    out.put_items(d.kept, [&](const std::pair<std::uint32_t, MotionRecord>& k) {
        out.put(k.first);
        save_motion_record(out, k.second);
    });
    put_pairs(out, d.jumps);
    put_pairs(out, d.kerfs);
    put_pairs(out, d.feeds);
    out.put_vector(d.pierces);
    d.line_index.save(out);
    out.put_items(d.marks, [&](const DiagnosticMark& m) { out.put_all(m.diagnostic, m.at); });
    put_pairs(out, d.concerned_motions);
    put_chunks(out, d.chunks);
    for (const std::size_t n : {d.blocks, d.block_words, d.curves}) out.put<std::uint64_t>(n);
    d.bbox.save(out);
    out.put(d.origin);
    return out.take();
}

namespace {

bool decode_into(Document& d, std::string_view wire, WireError& error) {
    Decoding w(wire, error);
    WireReader& in = w.in();
    if (!w.check(in.get_string(d.name), "name") || !w.check(get_setup(in, d.setup), "setup")) return false;
    d.profile = d.setup.profile;
    if (!w.check(restore_diagnostics(in, d.diagnostics), "diagnostics") ||
        !w.check(restore_stats(in, d.stats), "statistics") || !w.check(in.get_vector(d.motions), "motions") ||
        !w.check(in.get_vector(d.arc_centres), "arc centres") || !w.check(d.arc_rank.restore(in), "arc index") ||
        !w.check(get_kept(in, d.kept), "kept motions") || !w.check(get_pairs(in, d.jumps), "jumps") ||
        !w.check(get_pairs(in, d.kerfs), "kerfs") || !w.check(get_pairs(in, d.feeds), "feeds") ||
        !w.check(in.get_vector(d.pierces), "pierces") || !w.check(d.line_index.restore(in), "line index") ||
        !w.check(get_marks(in, d.marks), "diagnostic marks") ||
        !w.check(get_pairs(in, d.concerned_motions), "concerned motions") ||
        !w.check(get_chunks(in, d), "reader checkpoints"))
        return false;
    std::uint64_t blocks = 0, words = 0, curves = 0;
    if (!w.check(in.get(blocks) && in.get(words) && in.get(curves) && d.bbox.restore(in) && in.get(d.origin),
                 "counts") ||
        !w.at_end())
        return false;
    d.blocks = static_cast<std::size_t>(blocks);
    d.block_words = static_cast<std::size_t>(words);
    d.curves = static_cast<std::size_t>(curves);
    return true;
}

}  // namespace

std::unique_ptr<Document> decode_document(std::string_view wire, std::string& bytes, WireError& error) {
    auto doc = std::make_unique<Document>();
    doc->bytes = std::move(bytes);  // (before the readers are resumed: they keep a view of them)
    if (decode_into(*doc, wire, error)) return doc;
    bytes = std::move(doc->bytes);
    return nullptr;
}

std::string encode_diagnostics(const std::vector<Diagnostic>& diagnostics) {
    WireWriter out;
    save_diagnostics(out, diagnostics);
    return out.take();
}

bool decode_diagnostics(std::string_view wire, std::vector<Diagnostic>& diagnostics, WireError& error) {
    Decoding d(wire, error);
    return d.check(restore_diagnostics(d.in(), diagnostics), "diagnostics") && d.at_end();
}

}  // namespace essi::viewer
