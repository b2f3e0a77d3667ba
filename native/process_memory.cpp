#include "process_memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace essi::native {

void keep_freed_memory() {
#if defined(__GLIBC__)
    mallopt(M_TRIM_THRESHOLD, static_cast<int>(kKeptFreedBytes));
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(kOwnMappingBytes));
#endif
}

}  // namespace essi::native
