// The read result (essi/read.hpp): blocks, their words, the sparse word index, and appending chunks.
#include <algorithm>

#include "essi/read.hpp"

namespace essi {

std::span<const std::int32_t> Tape::words(std::size_t i) const {
    const std::size_t group = i / kWordIndexStride;
    std::size_t w = word_index_[group];
    for (std::size_t k = group * kWordIndexStride; k < i; ++k) w += blocks_[k].word_count();
    return {words_.data() + w, static_cast<std::size_t>(blocks_[i].word_count())};
}

std::span<const std::int32_t> Tape::WordCursor::next(std::size_t i) {
    while (block_ < i) word_ += tape_->blocks_[block_++].word_count();
    return {tape_->words_.data() + word_, static_cast<std::size_t>(tape_->blocks_[i].word_count())};
}

bool Tape::has_errors() const {
    return std::any_of(diagnostics_.begin(), diagnostics_.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

std::size_t Tape::memory_bytes() const {
    return blocks_.capacity() * sizeof(Block) + words_.capacity() * sizeof(std::int32_t) +
           word_index_.capacity() * sizeof(std::uint32_t);
}

void Tape::append(const Tape& chunk) {
    if (blocks_.empty()) first_block_ = chunk.first_block_;
    const std::size_t before = blocks_.size();
    const bool ended_before = has_end_;
    blocks_.append(chunk.blocks_.data(), chunk.blocks_.size());
    // The sparse word index of the whole: one entry per kWordIndexStride blocks, counted from block 0.
    std::size_t w = words_.size();
    for (std::size_t k = 0; k < chunk.blocks_.size(); ++k) {
        if ((before + k) % kWordIndexStride == 0) word_index_.push_back(static_cast<std::uint32_t>(w));
        w += chunk.blocks_[k].word_count();
    }
    words_.append(chunk.words_.data(), chunk.words_.size());
    diagnostics_.insert(diagnostics_.end(), chunk.diagnostics_.begin(), chunk.diagnostics_.end());
    // Program blocks: those up to the end block (a chunk after the end has end_block() == 0).
    if (!ended_before) end_block_ = before + chunk.end_block_;
    program_blocks_ += chunk.program_blocks_;
    has_end_ = has_end_ || chunk.has_end_;
}

void Tape::reserve(std::size_t blocks, std::size_t words) {
    blocks_.reserve(blocks);
    words_.reserve(words);
    word_index_.reserve(blocks / kWordIndexStride + 1);
}

void Tape::shrink_to_fit() {
    blocks_.shrink_to_fit();
    words_.shrink_to_fit();
    word_index_.shrink_to_fit();
    diagnostics_.shrink_to_fit();
}

}  // namespace essi
