// Phase 1, read: bytes -> blocks, each with its source position. No machine semantics beyond
// "what words does this block hold" (docs/semantics.md §1-2). One front end per input format (BlockReader).
//
// Memory: a block is 12 bytes plus 4 bytes per signed word, stored contiguously; the word index of a
// block is kept sparsely (one entry per kWordIndexStride blocks), so a tape of straight lines costs
// 20 bytes a block.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "essi/diagnostics.hpp"
#include "essi/lines.hpp"
#include "essi/profile.hpp"
#include "essi/wire.hpp"

namespace essi {

enum class BlockKind : std::uint8_t {
    Function,       // a machine function: code, no word ("7")
    FunctionValue,  // a machine function with a value (Woyda): code + 1 word ("39+1400")
    Motion,         // 2, 5 or 6 signed words; optionally with a head address in `code` ("1+100+0")
    Comment,        // a line inside a 3 ... 4 section (its text: the source line at `offset`)
    Percent,        // '%': initialisation / rewind-stop mark
    EndMark,        // '/' or '=' ending the program (dialect)
    Invalid,        // a block with a read error; the interpreter skips it
};

namespace detail {
// A growable array of plain values (blocks, words) that the reader's hot loop fills through a raw pointer:
// it makes room for a line's worth once (`room`), writes, then `commit`s what it wrote, instead of a
// capacity check per value. Growth is geometric, as std::vector's.
template <class T>
class PodArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
    PodArray() = default;
    PodArray(const PodArray& o) { append(o.data(), o.size()); }
    PodArray(PodArray&& o) noexcept
        : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)), cap_(std::exchange(o.cap_, 0)) {}
    PodArray& operator=(const PodArray& o) {
        if (this != &o) {
            size_ = 0;
            append(o.data(), o.size());
        }
        return *this;
    }
    PodArray& operator=(PodArray&& o) noexcept {
        std::swap(data_, o.data_);
        std::swap(size_, o.size_);
        std::swap(cap_, o.cap_);
        return *this;
    }
    ~PodArray() { std::free(data_); }

    [[nodiscard]] T* data() { return data_; }
    [[nodiscard]] const T* data() const { return data_; }
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] std::size_t capacity() const { return cap_; }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    T& back() { return data_[size_ - 1]; }
    [[nodiscard]] std::span<const T> span() const { return {data_, size_}; }

    void clear() { size_ = 0; }
    void truncate(std::size_t n) {
        if (n < size_) size_ = n;
    }
    void reserve(std::size_t n) {
        if (n > cap_) reallocate(n);
    }
    void push_back(const T& v) {
        if (size_ == cap_) reallocate(grown(size_ + 1));
        data_[size_++] = v;
    }
    void append(const T* p, std::size_t n) {
        if (n == 0) return;
        std::memcpy(room(n), p, n * sizeof(T));
        size_ += n;
    }
    // Room for `n` more values: where to write them (then commit how many were written).
    T* room(std::size_t n) {
        if (cap_ - size_ < n) reallocate(grown(size_ + n));
        return data_ + size_;
    }
    void commit(std::size_t n) { size_ += n; }
    // The values up to `end` (a pointer into the room made) are now part of the array.
    void commit_to(const T* end) { size_ = static_cast<std::size_t>(end - data_); }
    [[nodiscard]] T* end_of_room() { return data_ + cap_; }
    void shrink_to_fit() {
        if (cap_ != size_) reallocate(size_);
    }

private:
    [[nodiscard]] std::size_t grown(std::size_t need) const { return need > 2 * cap_ ? need : 2 * cap_; }
    void reallocate(std::size_t cap) {
        if (cap == 0) {
            std::free(data_);
            data_ = nullptr;
            cap_ = 0;
            return;
        }
        void* p = std::realloc(data_, cap * sizeof(T));
        if (p == nullptr) throw std::bad_alloc();  // as std::vector does
        data_ = static_cast<T*>(p);
        cap_ = cap;
    }
    T* data_ = nullptr;
    std::size_t size_ = 0, cap_ = 0;
};
}  // namespace detail

// One block. `code` is the leading unsigned number (function code or head address), or kNoCode.
struct Block {
    std::uint32_t offset = 0;  // byte offset of the block's first character
    std::uint32_t line = 0;    // 1-based line (every CR, LF, CR LF or LF CR counts one)
    std::uint16_t code = 0;
    BlockKind kind = BlockKind::Invalid;
    // low 4 bits: number of signed words (0-6); bit 4: sign of word 5 (TC) is '-' (a FunctionValue: its word is
    // in thousandths); bit 5: sign of word 6 (TP) is '-'; bit 6: block had a head address; bit 7: end of program
    std::uint8_t packed = 0;

    static constexpr std::uint16_t kNoCode = 0xFFFF;
    static constexpr std::uint8_t kWordCountMask = 0x0F;
    static constexpr std::uint8_t kTcNegative = 0x10;
    static constexpr std::uint8_t kTpNegative = 0x20;
    static constexpr std::uint8_t kHasAddress = 0x40;
    static constexpr std::uint8_t kProgramEnd = 0x80;  // this block ends the program (63, 64, / ...)
    // A FunctionValue whose word is the value in thousandths (an EIA dwell of 500 ms is 41 with 0.5 s: word 500).
    static constexpr std::uint8_t kValueThousandths = 0x10;

    [[nodiscard]] int word_count() const { return packed & kWordCountMask; }
    [[nodiscard]] bool has_code() const { return code != kNoCode; }
    [[nodiscard]] bool has_address() const { return (packed & kHasAddress) != 0; }
    [[nodiscard]] bool ends_program() const { return (packed & kProgramEnd) != 0; }
    // TC (word 5): true = '+' = counter-clockwise (ISO A.7)
    [[nodiscard]] bool tc_positive() const { return (packed & kTcNegative) == 0; }
    // TP (word 6): true = '+' = axis parallel to the transverse (Y) axis
    [[nodiscard]] bool tp_positive() const { return (packed & kTpNegative) == 0; }
    // A FunctionValue's value from its word.
    [[nodiscard]] double function_value(std::int32_t word) const {
        return (packed & kValueThousandths) != 0 ? word / 1000.0 : static_cast<double>(word);
    }
};
static_assert(sizeof(Block) == 12, "Block must stay compact");

// The read result: blocks, their words, and the diagnostics of reading.
class Tape {
public:
    static constexpr std::size_t kWordIndexStride = 64;

    [[nodiscard]] std::size_t size() const { return blocks_.size(); }
    [[nodiscard]] const Block& block(std::size_t i) const { return blocks_[i]; }
    [[nodiscard]] std::span<const Block> blocks() const { return blocks_.span(); }
    // The signed words of block i (random access; sequential walkers should use WordCursor).
    [[nodiscard]] std::span<const std::int32_t> words(std::size_t i) const;
    [[nodiscard]] std::span<const std::int32_t> all_words() const { return words_.span(); }
    [[nodiscard]] const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
    [[nodiscard]] bool has_errors() const;
    // Index of the first block after the program's end, or size() when the tape has no end.
    // In a chunk (TapeReader): the blocks of the chunk that belong to the program.
    [[nodiscard]] std::size_t end_block() const { return end_block_; }
    // Index, in the whole tape, of this chunk's first block (0 for a whole tape).
    [[nodiscard]] std::size_t first_block() const { return first_block_; }
    [[nodiscard]] bool has_program_end() const { return has_end_; }
    // Blocks of the program (those before end_block(), comment lines inside 3 ... 4 excluded): the block
    // count of the statistics (§9).
    [[nodiscard]] std::size_t program_blocks() const { return program_blocks_; }
    // Bytes held by blocks, words and the index (capacity, not size): the memory a tape costs.
    [[nodiscard]] std::size_t memory_bytes() const;

    // Appends the next chunk of the same tape (TapeReader, chunks in order): its blocks, words and
    // diagnostics; afterwards this tape equals read_tape() of the bytes read so far. Appending to an empty
    // tape takes the chunk's first_block().
    void append(const Tape& chunk);
    // Reserves room for `blocks` blocks and `words` words (before appending chunks).
    void reserve(std::size_t blocks, std::size_t words);
    // Frees the room reserved but not used (after the last append).
    void shrink_to_fit();

    // Walks the words of consecutive blocks without the index.
    class WordCursor {
    public:
        explicit WordCursor(const Tape& tape) : tape_(&tape) {}
        // Words of block i; blocks must be visited in increasing order.
        std::span<const std::int32_t> next(std::size_t i);

    private:
        const Tape* tape_;
        std::size_t block_ = 0;
        std::size_t word_ = 0;
    };

private:
    friend class BlockReader;  // the front ends write the arrays (BlockReader's accessors)
    detail::PodArray<Block> blocks_;
    detail::PodArray<std::int32_t> words_;
    detail::PodArray<std::uint32_t> word_index_;  // first word of block k*kWordIndexStride
    std::vector<Diagnostic> diagnostics_;
    std::size_t end_block_ = 0;
    std::size_t first_block_ = 0;
    std::size_t program_blocks_ = 0;
    bool has_end_ = false;
};

// The formats a tape can be written in. Each has its front end in core/read/ (one file each, a BlockReader driven
// by the chunk loop of core/read/reader_driver.hpp): ESSI (essi_reader.cpp), EIA RS-274 (eia_reader.cpp).
enum class InputFormat : std::uint8_t { Essi, Eia };
inline constexpr InputFormat kInputFormats[] = {InputFormat::Essi, InputFormat::Eia};
[[nodiscard]] const char* input_format_name(InputFormat f);  // "essi", "eia"
// The format a name names ("essi", "eia": input_format_name's), nullopt for any other text.
[[nodiscard]] std::optional<InputFormat> parse_input_format(std::string_view name);

// A front end: bytes -> blocks with their positions (byte offset, line), a chunk at a time, every problem a
// diagnostic (never an exception). The blocks mean the same whatever format they were read from: the interpreter
// runs them without knowing the format, so a format is added by a BlockReader beside the others and a value of
// InputFormat, and nothing after the read changes.
class BlockReader {
public:
    virtual ~BlockReader() = default;
    // Empties `chunk` and reads up to `max_blocks` more blocks into it, with the diagnostics found meanwhile.
    // Returns false when the tape is done (nothing was read). Chunks come in tape order; after the last, the
    // chunks appended together are what reading the whole tape at once gives.
    virtual bool read_chunk(Tape& chunk, std::size_t max_blocks) = 0;
    // Reserves in `tape` the room the whole tape needs (a cheap pass over the bytes), before one read_chunk of
    // everything.
    virtual void reserve_whole(Tape& tape) const = 0;
    // A copy that goes on from where this one is.
    [[nodiscard]] virtual std::unique_ptr<BlockReader> clone() const = 0;
    // The bytes this reader holds (what keeping a copy costs).
    [[nodiscard]] virtual std::size_t state_bytes() const = 0;
    // The state as bytes: where the reader is in the tape and what it has read that the rest depends on (modes,
    // the errors so far); restore() puts it back into a reader of the same bytes, profile and format, which then
    // reads on as this one would. restore() is false when the bytes are not such a state (cut short, another size
    // of tape).
    virtual void save(WireWriter& out) const = 0;
    [[nodiscard]] virtual bool restore(WireReader& in) = 0;

protected:
    // What a front end writes into a Tape.
    static detail::PodArray<Block>& blocks_of(Tape& t) { return t.blocks_; }
    static detail::PodArray<std::int32_t>& words_of(Tape& t) { return t.words_; }
    static detail::PodArray<std::uint32_t>& word_index_of(Tape& t) { return t.word_index_; }
    static std::vector<Diagnostic>& diagnostics_of(Tape& t) { return t.diagnostics_; }
    static std::size_t& end_block_of(Tape& t) { return t.end_block_; }
    static std::size_t& first_block_of(Tape& t) { return t.first_block_; }
    static std::size_t& program_blocks_of(Tape& t) { return t.program_blocks_; }
    static bool& has_end_of(Tape& t) { return t.has_end_; }
};

// The front end of `format` for `bytes` and `profile` (both must outlive it: it keeps references).
[[nodiscard]] std::unique_ptr<BlockReader> make_block_reader(InputFormat format, std::string_view bytes,
                                                             const Profile& profile);

// Reads a tape. Never throws; every problem is a diagnostic in the result.
[[nodiscard]] Tape read_tape(std::string_view bytes, const Profile& profile, InputFormat format = InputFormat::Essi);

// Reads a tape a chunk of blocks at a time, so that a checker can interpret each chunk while it is
// still in cache, and never holds the whole tape (the same reader as read_tape; the same results). The bytes and
// the profile must outlive the reader.
class TapeReader {
public:
    TapeReader(std::string_view bytes, const Profile& profile, InputFormat format = InputFormat::Essi);
    ~TapeReader();
    TapeReader(TapeReader&&) noexcept;
    TapeReader& operator=(TapeReader&&) noexcept;
    // A copy goes on from where the original is: keep one before a chunk to read that chunk again later.
    TapeReader(const TapeReader& other);
    TapeReader& operator=(const TapeReader& other);
    // The bytes a reader holds (what keeping a copy costs).
    [[nodiscard]] std::size_t state_bytes() const;
    // The reader's state as bytes, to read on from in another instance of this build (the viewer's worker hands
    // its page the reader before each chunk): resume() with the same bytes, profile and format.
    [[nodiscard]] std::string checkpoint() const;
    // A reader of `bytes` that reads on from `checkpoint`; nullopt when it is not a checkpoint of a reader of
    // this format and these bytes' size.
    [[nodiscard]] static std::optional<TapeReader> resume(std::string_view bytes, const Profile& profile,
                                                          InputFormat format, std::string_view checkpoint);
    // Empties `chunk` and reads up to `max_blocks` more blocks into it, with the diagnostics found
    // meanwhile. Returns false when the tape is done (nothing was read).
    bool read_chunk(Tape& chunk, std::size_t max_blocks);

private:
    std::unique_ptr<BlockReader> impl_;
    InputFormat format_ = InputFormat::Essi;
};

}  // namespace essi
