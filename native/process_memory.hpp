// How the process's heap hands memory back to the system, for a command that runs once and ends.
#pragma once

#include <cstddef>

namespace essi::native {

// What the heap keeps of what is freed before it gives it back (glibc's M_TRIM_THRESHOLD), and the size from which a
// block is a mapping of its own, unmapped when freed (M_MMAP_THRESHOLD). Not larger: a vector that grows past it is
// moved by mremap, where one in the heap is copied and leaves its old block behind (a tape of 100 000 parabolas took
// 91 MB instead of 57 MB with 32 MB here).
constexpr std::size_t kKeptFreedBytes = std::size_t{256} << 20;
constexpr std::size_t kOwnMappingBytes = std::size_t{4} << 20;

// For a command that runs once and ends (check, stats, ...; not `essi serve`): memory freed stays with the process to
// be used again. By default glibc trims the heap's top and unmaps large blocks as soon as they are freed, so each
// plate of the cut plan, each chunk's buffers and each report faults its pages in afresh (a check of the 100 MB nest:
// 7 500 page faults, 0.1-0.3 s of system time on a VM). The peak stays what the command holds at once.
void keep_freed_memory();

}  // namespace essi::native
