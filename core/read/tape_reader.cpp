// Reading a tape whole or a chunk at a time, through the front end of its format (essi/read.hpp).
#include <limits>

#include "essi/read.hpp"

namespace essi {

std::unique_ptr<BlockReader> make_essi_reader(std::string_view bytes, const Profile& profile);  // essi_reader.cpp
std::unique_ptr<BlockReader> make_eia_reader(std::string_view bytes, const Profile& profile);   // eia_reader.cpp

const char* input_format_name(InputFormat f) { return f == InputFormat::Eia ? "eia" : "essi"; }

std::optional<InputFormat> parse_input_format(std::string_view name) {
    for (const InputFormat f : kInputFormats)
        if (name == input_format_name(f)) return f;
    return std::nullopt;
}

std::unique_ptr<BlockReader> make_block_reader(InputFormat format, std::string_view bytes, const Profile& profile) {
    switch (format) {
        case InputFormat::Essi: break;
        case InputFormat::Eia: return make_eia_reader(bytes, profile);
    }
    return make_essi_reader(bytes, profile);
}

Tape read_tape(std::string_view bytes, const Profile& profile, InputFormat format) {
    Tape tape;
    const auto reader = make_block_reader(format, bytes, profile);
    reader->reserve_whole(tape);
    (void)reader->read_chunk(tape, std::numeric_limits<std::size_t>::max());
    return tape;
}

TapeReader::TapeReader(std::string_view bytes, const Profile& profile, InputFormat format)
    : impl_(make_block_reader(format, bytes, profile)), format_(format) {}
TapeReader::~TapeReader() = default;
TapeReader::TapeReader(TapeReader&&) noexcept = default;
TapeReader& TapeReader::operator=(TapeReader&&) noexcept = default;
TapeReader::TapeReader(const TapeReader& other) : impl_(other.impl_->clone()), format_(other.format_) {}
TapeReader& TapeReader::operator=(const TapeReader& other) {
    if (this != &other) {
        impl_ = other.impl_->clone();
        format_ = other.format_;
    }
    return *this;
}
std::size_t TapeReader::state_bytes() const { return sizeof(TapeReader) + impl_->state_bytes(); }

std::string TapeReader::checkpoint() const {
    WireWriter out;
    out.put(format_);
    impl_->save(out);
    return out.take();
}

std::optional<TapeReader> TapeReader::resume(std::string_view bytes, const Profile& profile, InputFormat format,
                                             std::string_view checkpoint) {
    WireReader in(checkpoint);
    InputFormat saved = InputFormat::Essi;
    if (!in.get(saved) || saved != format) return std::nullopt;
    TapeReader reader(bytes, profile, format);
    if (!reader.impl_->restore(in) || !in.at_end()) return std::nullopt;
    return reader;
}

bool TapeReader::read_chunk(Tape& chunk, std::size_t max_blocks) { return impl_->read_chunk(chunk, max_blocks); }

}  // namespace essi
