#include "harness/results/markup_escape.h"

#include <gtest/gtest.h>

namespace holebench::harness {
namespace {

// A Markdown cell keeps its row: '|' escaped, line breaks become spaces, the rest unchanged.
TEST(MarkupEscape, MarkdownCell) {
  EXPECT_EQ(markdown_cell("box/corner|liepa_cgal|no_user|0|0"),
            "box/corner\\|liepa_cgal\\|no_user\\|0\\|0");
  EXPECT_EQ(markdown_cell("two\nlines\r\n"), "two lines  ");
  EXPECT_EQ(markdown_cell("hole_hausdorff_rel_diag"), "hole_hausdorff_rel_diag");
}

// LaTeX's ten special characters, each as LaTeX prints it.
TEST(MarkupEscape, LatexEscape) {
  EXPECT_EQ(latex_escape("slice_loft"), "slice\\_loft");
  EXPECT_EQ(latex_escape("a&b%c$d#e{f}"), "a\\&b\\%c\\$d\\#e\\{f\\}");
  EXPECT_EQ(latex_escape("~^\\"), "\\textasciitilde{}\\textasciicircum{}\\textbackslash{}");
}

// XML: the five entities; line breaks kept in content, as character references in attributes.
TEST(MarkupEscape, XmlEscape) {
  EXPECT_EQ(xml_escape("<a href=\"x\">'&'</a>"),
            "&lt;a href=&quot;x&quot;&gt;&apos;&amp;&apos;&lt;/a&gt;");
  EXPECT_EQ(xml_escape("a\nb"), "a\nb");
  EXPECT_EQ(xml_escape("a\nb", true), "a&#10;b");
  EXPECT_EQ(xml_escape(std::string("bell\x07")), "bell?");
}

}  // namespace
}  // namespace holebench::harness
