#include "harness/run/memory_limit.h"

#include <sys/resource.h>

#include <fmt/format.h>

#include <cctype>
#include <cstring>
#include <stdexcept>

namespace holebench::harness {

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

std::string lower(std::string text) {
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The factor of a unit ("", "b", "k", "kib", "m", "mib", "g", "gib", "t", "tib"); 0: unknown.
std::uint64_t unit_factor(const std::string& unit) {
  if (unit.empty() || unit == "b")
    return 1;
  const char prefix = unit[0];
  const std::string rest = unit.substr(1);
  if (rest != "" && rest != "ib" && rest != "b")
    return 0;
  switch (prefix) {
    case 'k':
      return 1024ull;
    case 'm':
      return 1024ull * 1024ull;
    case 'g':
      return kGibibyte;
    case 't':
      return 1024ull * kGibibyte;
  }
  return 0;
}

}  // namespace

std::uint64_t parse_memory_size(const std::string& text) {
  const std::string t = lower(text);
  if (t == "none")
    return 0;
  std::size_t end = 0;
  while (end < t.size() && (std::isdigit(static_cast<unsigned char>(t[end])) || t[end] == '.'))
    ++end;
  std::size_t unit_start = end;
  while (unit_start < t.size() && t[unit_start] == ' ')
    ++unit_start;
  const std::string number = t.substr(0, end);
  const std::uint64_t factor = unit_factor(t.substr(unit_start));
  double value = 0.0;
  try {
    std::size_t used = 0;
    value = number.empty() ? -1.0 : std::stod(number, &used);
    if (used != number.size())
      value = -1.0;
  } catch (const std::exception&) {
    value = -1.0;
  }
  const double bytes = value * static_cast<double>(factor);
  if (factor == 0 || !(value >= 0.0) || !(bytes < 1.8e19)) {
    throw std::invalid_argument("memory size '" + text +
                                "' is not a size such as 4G, 512MiB or 0 (no limit)");
  }
  return static_cast<std::uint64_t>(bytes);
}

std::string format_memory_size(std::uint64_t bytes) {
  if (bytes == 0)
    return "none";
  if (bytes % kGibibyte == 0)
    return fmt::format("{} GiB", bytes / kGibibyte);
  if (bytes % (1024ull * 1024ull) == 0)
    return fmt::format("{} MiB", bytes / (1024ull * 1024ull));
  return fmt::format("{} bytes", bytes);
}

MemoryLimitResult apply_memory_limit(std::uint64_t bytes) {
  MemoryLimitResult result;
  if (bytes == 0)
    return result;
  if (kAddressSanitizer) {
    result.note = "not applied under AddressSanitizer";
    return result;
  }
  rlimit limit{};
  limit.rlim_cur = static_cast<rlim_t>(bytes);
  limit.rlim_max = static_cast<rlim_t>(bytes);
  if (::setrlimit(RLIMIT_AS, &limit) != 0) {
    result.note = std::string("setrlimit(RLIMIT_AS): ") + std::strerror(errno);
    return result;
  }
  result.applied = true;
  return result;
}

bool message_reports_out_of_memory(const std::string& message) {
  for (const char* sign :
       {"bad_alloc", "MemoryError", "Cannot allocate memory", "out of memory", "Out of memory"}) {
    if (message.find(sign) != std::string::npos)
      return true;
  }
  return false;
}

}  // namespace holebench::harness
