// Case ids parsed once (generators/case_id.h): every id the catalog lists parses, to its own
// family and to fields that put together give the id again; the catalog's unknown ids keep
// their one-line error; texts of no family's shape do not parse.
#include "generators/case_id.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace holebench::generators {
namespace {

// The id put together again from its parsed fields, by the shapes of case_id.h.
std::string joined(const CaseId& id) {
  switch (id.kind) {
    case CaseIdKind::Box:
      return id.family + "/" + id.target;
    case CaseIdKind::Brep:
      return id.text;  // the catalogue's name: not split
    case CaseIdKind::Crease:
      return id.family + "/" + id.model + "/" + id.target;
    case CaseIdKind::FacesRemoved:
      return id.family + "/" + id.model + "/faces/" + id.target;
    case CaseIdKind::Punched:
      return id.family + "/" + id.model + "/" + id.target + "/" + id.size;
  }
  return {};
}

TEST(CaseId, EveryListedIdParsesToItsFamilyAndItsFields) {
  const auto cases = list_cases();
  ASSERT_GT(cases.size(), 100u);
  for (const auto& descriptor : cases) {
    const auto id = parse_case_id(descriptor.id);
    ASSERT_TRUE(id.has_value()) << descriptor.id;
    EXPECT_EQ(id->family, descriptor.family) << descriptor.id;
    EXPECT_EQ(joined(*id), descriptor.id);
    if (id->kind == CaseIdKind::Punched) {
      EXPECT_TRUE(id->size == "small" || id->size == "large") << descriptor.id;
    }
  }
}

TEST(CaseId, TheFieldsAreNamed) {
  const auto punched = parse_case_id("cad/fandisk/corner_ccc/small");
  ASSERT_TRUE(punched);
  EXPECT_EQ(punched->kind, CaseIdKind::Punched);
  EXPECT_EQ(punched->model, "fandisk");
  EXPECT_EQ(punched->target, "corner_ccc");
  EXPECT_EQ(punched->size, "small");
  const auto removed = parse_case_id("file/part/faces/3+7");
  ASSERT_TRUE(removed);
  EXPECT_EQ(removed->kind, CaseIdKind::FacesRemoved);
  EXPECT_EQ(removed->model, "part");
  EXPECT_EQ(removed->target, "3+7");
  const auto crease = parse_case_id("crease/fandisk/concave_corner");
  ASSERT_TRUE(crease);
  EXPECT_EQ(crease->kind, CaseIdKind::Crease);
  EXPECT_EQ(crease->target, "concave_corner");
  const auto box = parse_case_id("box/edge");
  ASSERT_TRUE(box);
  EXPECT_EQ(box->kind, CaseIdKind::Box);
  EXPECT_EQ(box->target, "edge");
}

TEST(CaseId, TextsOfNoFamilysShapeDoNotParse) {
  for (const char* text : {"", "box", "box/edge/small", "crease/fandisk", "cad/fandisk/corner",
                           "solid/l_block/edge_convex/small/extra", "sphere/a/b/c", "/a/b/c"}) {
    EXPECT_FALSE(parse_case_id(text).has_value()) << text;
  }
}

TEST(CaseId, AnUnknownIdKeepsTheCatalogsError) {
  for (const char* text : {"sphere/a/b/c", "box/nowhere", "solid/l_block/edge_convex/huge",
                           "file/nomodel/faces/bogus"}) {
    try {
      make_case(text);
      ADD_FAILURE() << text << " was made";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("unknown case id '") + text + "' (see `holebench cases list`)");
    }
  }
}

}  // namespace
}  // namespace holebench::generators
