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

bool BlockReader::begin_chunk(Tape& chunk, std::size_t first_block, bool first_chunk, std::string_view bytes) {
    chunk.blocks_.clear();
    chunk.words_.clear();
    chunk.word_index_.clear();
    chunk.diagnostics_.clear();
    chunk.first_block_ = first_block;
    chunk.has_end_ = false;
    if (!first_chunk || bytes.size() <= std::numeric_limits<std::uint32_t>::max()) return false;
    chunk.diagnostics_.push_back(
        make_diagnostic(Severity::Error, DiagCode::E117_TapeTooLarge, 0, 0, Msg::ReadTapeTooLarge, {bytes.size()}));
    return true;
}

void BlockReader::mark_program_end(Tape& chunk) {
    chunk.blocks_.back().packed |= Block::kProgramEnd;
    chunk.has_end_ = true;
    chunk.end_block_ = chunk.blocks_.size();
}

void BlockReader::finish_chunk(Tape& chunk, bool ended_before, bool ended, std::size_t comments) {
    if (ended_before) chunk.end_block_ = 0;
    else if (!ended) chunk.end_block_ = chunk.blocks_.size();
    // (when the end came in this chunk, mark_program_end set end_block_)
    chunk.program_blocks_ = chunk.end_block_ - (ended_before ? 0 : comments);
}

void BlockReader::report_tape_end(Tape& chunk, const Profile& profile, std::size_t total_blocks, bool ended,
                                  std::uint32_t last_line) {
    if (total_blocks == 0) {
        chunk.diagnostics_.push_back(make_diagnostic(Severity::Error, DiagCode::E113_EmptyTape, 1, 1, Msg::ReadEmptyTape));
    } else if (!ended && !profile.end_at_data_end) {
        chunk.diagnostics_.push_back(make_diagnostic(Severity::Warning, DiagCode::W114_NoProgramEnd, last_line, 1,
                                                     Msg::ReadNoProgramEnd, {end_codes_arg(profile)}));
    }
}

Tape read_tape(std::string_view bytes, const Profile& profile, InputFormat format) {
    Tape tape;
    const auto reader = make_block_reader(format, bytes, profile);
    reader->reserve_whole(tape);
    (void)reader->read_chunk(tape, std::numeric_limits<std::size_t>::max());
    return tape;
}

TapeReader::TapeReader(std::string_view bytes, const Profile& profile, InputFormat format)
    : impl_(make_block_reader(format, bytes, profile)) {}
TapeReader::~TapeReader() = default;
TapeReader::TapeReader(TapeReader&&) noexcept = default;
TapeReader& TapeReader::operator=(TapeReader&&) noexcept = default;
TapeReader::TapeReader(const TapeReader& other) : impl_(other.impl_->clone()) {}
TapeReader& TapeReader::operator=(const TapeReader& other) {
    if (this != &other) impl_ = other.impl_->clone();
    return *this;
}
std::size_t TapeReader::state_bytes() const { return sizeof(TapeReader) + impl_->state_bytes(); }

bool TapeReader::read_chunk(Tape& chunk, std::size_t max_blocks) { return impl_->read_chunk(chunk, max_blocks); }

}  // namespace essi
