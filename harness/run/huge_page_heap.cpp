#include "harness/run/huge_page_heap.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace holebench::harness {

namespace {
constexpr const char* kHugePageTunable = "glibc.malloc.hugetlb";
}

std::string tunables_with_huge_page_heap(const std::string& current) {
  if (current.find(kHugePageTunable) != std::string::npos)
    return current;
  const std::string tunable = std::string(kHugePageTunable) + "=1";
  return current.empty() ? tunable : current + ":" + tunable;
}

bool huge_pages_allowed_by(const std::string& enabled_file_text) {
  return enabled_file_text.find("[always]") != std::string::npos ||
         enabled_file_text.find("[madvise]") != std::string::npos;
}

void restart_with_huge_page_heap(char** argv) {
  const char* current = std::getenv("GLIBC_TUNABLES");
  const std::string now = current ? current : "";
  const std::string wanted = tunables_with_huge_page_heap(now);
  if (wanted == now)
    return;
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::stringstream mode;
  mode << file.rdbuf();
  if (!huge_pages_allowed_by(mode.str()))
    return;
  if (::setenv("GLIBC_TUNABLES", wanted.c_str(), 1) != 0)
    return;
  ::execv("/proc/self/exe", argv);
  // exec failed (no /proc): go on as we are, without the tunable in our own name.
  if (current)
    ::setenv("GLIBC_TUNABLES", current, 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
}

}  // namespace holebench::harness
