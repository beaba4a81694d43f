// A case id, parsed once: its family and the fields the family's ids are made of
// (docs/generators.md, `holebench cases list`). The catalog (case_catalog.cpp) makes a case by
// dispatching on the parsed id instead of comparing text fields.
//
//   box/<target>                       target: face_interior, edge, corner
//   brep/<rest>                        the synthetic B-Rep catalogue's name (brep_catalogue.cpp)
//   crease/<model>/<creases>           creases: 1, 2, 3 or concave_corner
//   solid|cad|file/<model>/<target>/<size>   a punched hole; size: a punch_size_classes() name
//   file/<model>/faces/<face set>      whole B-Rep faces removed (face_removal.h)
//   file/<model>/hole/<i>[/rings-<r>]  an open mesh's real hole i, as it is or enlarged by r
//                                      rings (real_holes.h)
#pragma once

#include <optional>
#include <string>

namespace holebench::generators {

enum class CaseIdKind {
  Box,           ///< box/<target>
  Brep,          ///< brep/...
  Crease,        ///< crease/<model>/<creases>
  Punched,       ///< <solid|cad|file>/<model>/<target>/<size>
  FacesRemoved,  ///< file/<model>/faces/<face set>
  RealHole,      ///< file/<model>/hole/<i>[/rings-<r>] (real_holes.h)
};

struct CaseId {
  std::string text;  ///< the id as given, e.g. "cad/fandisk/corner_ccc/small"
  CaseIdKind kind = CaseIdKind::Box;
  std::string family;  ///< its first field: box, brep, crease, solid, cad, file
  std::string model;   ///< the model's name (crease, punched, faces removed); else empty
  /// box: the box hole's target; punched: the punch target's kind (punch_targets.h); crease:
  /// "1", "2", "3" or "concave_corner"; faces removed: the face set's name; real hole: its
  /// index; brep: empty.
  std::string target;
  /// punched: the size class's name ("small", "large"); real hole: "rings-<r>" or empty;
  /// else empty
  std::string size;
};

/// Parses `text` by the shapes above. Returns nothing where the text has none of them (a
/// family the catalog does not know, or the wrong number of fields for its family); whether
/// the model, target and size exist is the catalog's question, not the parser's.
std::optional<CaseId> parse_case_id(const std::string& text);

}  // namespace holebench::generators
