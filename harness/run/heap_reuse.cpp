#include "harness/run/heap_reuse.h"

#include <malloc.h>

namespace holebench::harness {

void keep_freed_heap_memory() {
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 64 << 20);
}

}  // namespace holebench::harness
