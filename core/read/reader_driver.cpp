// What every front end shares (reader_driver.hpp): the state kept, and the chunk keeping.
#include "reader_driver.hpp"

#include <cstdio>
#include <utility>

namespace essi::detail {

std::string hex_byte(unsigned char c) {
    char buf[4];
    std::snprintf(buf, sizeof buf, "%02X", c);
    return buf;
}

ReaderState::ReaderState(std::string_view bytes, const Profile& profile, Msg too_many_errors)
    : src_(bytes), profile_(profile), too_many_errors_(too_many_errors) {
    for (const EndCode& e : profile.end_codes)
        if (e.function >= 0 && e.function < fn::kCodeCount) end_function_[static_cast<std::size_t>(e.function)] = true;
}

void ReaderState::report(Severity sev, DiagCode code, std::uint32_t offset, Msg msg, MessageArgs args) {
    if (stopped_) return;
    diagnostics_of(*chunk_).push_back(make_diagnostic(sev, code, line_, column(offset), msg, std::move(args)));
    if (sev == Severity::Error && ++errors_ >= kMaxReadErrors) {
        diagnostics_of(*chunk_).push_back(make_diagnostic(Severity::Error, DiagCode::E115_TooManyErrors, line_,
                                                          column(offset), too_many_errors_, {kMaxReadErrors}));
        stopped_ = true;
    }
}

void ReaderState::mark_program_end() {
    Tape& t = *chunk_;
    ended_ = true;
    end_line_ = line_;
    blocks_of(t).back().packed |= Block::kProgramEnd;
    has_end_of(t) = true;
    end_block_of(t) = blocks_of(t).size();
}

bool ReaderState::is_end_mark(char mark) const {
    return std::any_of(profile_.end_codes.begin(), profile_.end_codes.end(),
                       [&](const EndCode& e) { return e.function < 0 && e.mark == mark; });
}

bool ReaderState::begin_chunk(Tape& chunk) {
    chunk_ = &chunk;
    chunk_blocks_ = 0;
    chunk_comments_ = 0;
    blocks_of(chunk).clear();
    words_of(chunk).clear();
    word_index_of(chunk).clear();
    diagnostics_of(chunk).clear();
    first_block_of(chunk) = total_blocks_;
    has_end_of(chunk) = false;
    if (started_) return false;
    started_ = true;
    if (src_.size() > std::numeric_limits<std::uint32_t>::max()) {
        diagnostics_of(chunk).push_back(
            make_diagnostic(Severity::Error, DiagCode::E117_TapeTooLarge, 0, 0, Msg::ReadTapeTooLarge, {src_.size()}));
        stopped_ = true;
        return false;
    }
    return true;
}

bool ReaderState::finish_chunk(Tape& chunk, std::uint32_t pos) {
    pos_ = pos;
    total_blocks_ += blocks_of(chunk).size();
    // The chunk's program blocks: all, up to the end block (mark_program_end set it), none when the end came in
    // an earlier chunk; comments (only before the end) do not count.
    const bool ended_before = ended_ && !has_end_of(chunk);
    if (ended_before) end_block_of(chunk) = 0;
    else if (!ended_) end_block_of(chunk) = blocks_of(chunk).size();
    program_blocks_of(chunk) = end_block_of(chunk) - (ended_before ? 0 : chunk_comments_);
    if (pos < readable_size() && !stopped_ && !after_end_seen_) return false;
    finished_ = true;
    return !stopped_;
}

void ReaderState::save_state(WireWriter& out) const {
    out.put<std::uint64_t>(src_.size());
    for (const std::uint32_t v : {pos_, line_, line_begin_, last_line_, end_line_, percent_line_, percent_column_})
        out.put(v);
    out.put(total_blocks_);
    out.put(errors_);
    for (const bool b : {started_, finished_, stopped_, after_end_seen_, ended_, program_started_}) out.put(b);
}

bool ReaderState::restore_state(WireReader& in) {
    std::uint64_t size = 0;
    if (!in.get(size) || size != src_.size()) return false;
    for (std::uint32_t* v : {&pos_, &line_, &line_begin_, &last_line_, &end_line_, &percent_line_, &percent_column_})
        if (!in.get(*v)) return false;
    if (!in.get(total_blocks_) || !in.get(errors_)) return false;
    for (bool* b : {&started_, &finished_, &stopped_, &after_end_seen_, &ended_, &program_started_})
        if (!in.get(*b)) return false;
    return pos_ <= src_.size();
}

void ReaderState::report_tape_end(Tape& chunk) {
    if (total_blocks_ == 0) {
        diagnostics_of(chunk).push_back(
            make_diagnostic(Severity::Error, DiagCode::E113_EmptyTape, 1, 1, Msg::ReadEmptyTape));
    } else if (!ended_ && !profile_.end_at_data_end) {
        diagnostics_of(chunk).push_back(make_diagnostic(Severity::Warning, DiagCode::W114_NoProgramEnd, last_line_, 1,
                                                        Msg::ReadNoProgramEnd, {end_codes_arg(profile_)}));
    }
}

}  // namespace essi::detail
