// A run's processes take their heap in transparent huge pages (2 MiB) where the system allows
// it, which cuts the page faults of every job's process by about half.
//
// Each job runs in a process forked from its group's (harness/run/process_pool.h); all the
// memory it allocates is new to it, and each 4 KiB page costs a page fault on first touch.
// On this project's machines (virtual machines) a fault costs several microseconds, and the
// smoke suite's faults took a fifth of its processor time. glibc (2.35 and later) can ask the
// kernel for huge pages for its heap (the tunable glibc.malloc.hugetlb=1: madvise
// MADV_HUGEPAGE on the memory it takes), one fault per 2 MiB; it reads its tunables once,
// when the program starts, so the runner starts itself again with the tunable set. Results
// do not change: only where the allocator's memory comes from.
#pragma once

#include <string>

namespace holebench::harness {

/// The GLIBC_TUNABLES value that adds glibc.malloc.hugetlb=1 to `current` (the variable's
/// value, empty when unset); `current` itself when it already names glibc.malloc.hugetlb (the
/// user's own choice, or this process already started again).
std::string tunables_with_huge_page_heap(const std::string& current);

/// Whether the kernel gives transparent huge pages to memory that asks for them, from the
/// text of /sys/kernel/mm/transparent_hugepage/enabled ("always [madvise] never"): the mode
/// in brackets is "always" or "madvise". Empty text (no such file): false.
bool huge_pages_allowed_by(const std::string& enabled_file_text);

/// Starts this program again (/proc/self/exe, the same arguments) with glibc.malloc.hugetlb=1
/// added to GLIBC_TUNABLES, when huge pages are available and the tunable is not set yet.
/// Returns only when it does not (nothing to do, or exec failed): the program goes on as it
/// is. Call it first in main(), before any thread or output.
void restart_with_huge_page_heap(char** argv);

}  // namespace holebench::harness
