// The heap in huge pages (harness/run/huge_page_heap.h): the GLIBC_TUNABLES value a run
// starts itself again with, and the kernel's mode read from its file. The restart itself is
// tested end to end by huge_page_heap_run_test.sh.
#include "harness/run/huge_page_heap.h"

#include <gtest/gtest.h>

namespace holebench::harness {
namespace {

TEST(HugePageHeap, TunableAddedToNothingOrToTheUsersOwn) {
  EXPECT_EQ(tunables_with_huge_page_heap(""), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_page_heap("glibc.malloc.check=3"),
            "glibc.malloc.check=3:glibc.malloc.hugetlb=1");
}

TEST(HugePageHeap, TheUsersOwnHugePageChoiceIsKept) {
  EXPECT_EQ(tunables_with_huge_page_heap("glibc.malloc.hugetlb=0"), "glibc.malloc.hugetlb=0");
  EXPECT_EQ(tunables_with_huge_page_heap("glibc.malloc.check=3:glibc.malloc.hugetlb=2"),
            "glibc.malloc.check=3:glibc.malloc.hugetlb=2");
}

TEST(HugePageHeap, KernelModeReadFromItsFile) {
  EXPECT_TRUE(huge_pages_allowed_by("always [madvise] never\n"));
  EXPECT_TRUE(huge_pages_allowed_by("[always] madvise never\n"));
  EXPECT_FALSE(huge_pages_allowed_by("always madvise [never]\n"));
  EXPECT_FALSE(huge_pages_allowed_by(""));
}

}  // namespace
}  // namespace holebench::harness
