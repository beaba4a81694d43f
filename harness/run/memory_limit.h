// The memory limit of a job: how much address space a job's process (and every program it
// starts) may take, and how a job that ran out of it is recognised.
//
// The limit is RLIMIT_AS (setrlimit), set in the job's child process right after the fork,
// so it covers the child's whole address space, including what it inherits from the runner
// (the case catalog), and is inherited by the programs the job starts (an external method).
// Past the limit an allocation fails: C++ code throws std::bad_alloc, a Python program raises
// MemoryError, C code gets a null pointer. The runner records such a job as `out_of_memory`
// (harness/run/job.h) and the run goes on. RLIMIT_AS limits virtual memory, not resident
// memory: a method that maps much more than it touches is stopped early; the default (4 GiB)
// is far above what the built-in methods map on the nightly suite's cases.
//
// Under AddressSanitizer (the debug preset) the limit is not applied: ASan reserves terabytes
// of address space for its shadow memory and would fail at once.
#pragma once

#include <cstdint>
#include <string>

namespace holebench::harness {

/// One gibibyte.
inline constexpr std::uint64_t kGibibyte = 1024ull * 1024ull * 1024ull;

/// The default limit of a job's address space, when the suite names none.
inline constexpr std::uint64_t kDefaultMemoryLimitBytes = 4 * kGibibyte;

/// Bytes from a size as a person writes it: a number with an optional unit, "4G", "4GiB",
/// "512M", "512MiB", "65536K", "1073741824" (bytes); "0" or "none" for no limit. The units
/// are binary (G = GiB). Throws std::invalid_argument naming the text otherwise.
std::uint64_t parse_memory_size(const std::string& text);

/// "4 GiB", "512 MiB", "1000 bytes", "none" (0).
std::string format_memory_size(std::uint64_t bytes);

struct MemoryLimitResult {
  bool applied = false;  ///< false: no limit asked for (0), or not possible (see `note`)
  std::string note;      ///< why it was not applied, if it was asked for
};

/// Limits this process's address space to `bytes` (RLIMIT_AS, soft and hard; 0: none). Called
/// in a job's child process. Never throws.
MemoryLimitResult apply_memory_limit(std::uint64_t bytes);

/// Whether a failure message says the failing code ran out of memory: std::bad_alloc, a
/// Python MemoryError, "Cannot allocate memory" (ENOMEM), "out of memory".
bool message_reports_out_of_memory(const std::string& message);

}  // namespace holebench::harness
