// The catalog of cases: every case has a stable id and is fully determined by its id, its
// seed and its noise level.
//
// Families and their ids:
//   box/<target>                      the walking skeleton's three box holes
//   brep/...                          synthetic planar B-Rep cases (docs/cases.md)
//   cad/<model>/<target>/<size>       holes punched into CGAL's CAD meshes
//   solid/<name>/<target>/<size>      holes punched into procedural solids
//   file/<stem>/<target>/<size>       holes punched into a user's mesh files
//   file/<stem>/faces/<ids>           B-Rep files: whole faces removed ("6-7-11": faces 6, 7
//                                     and 11; generators/face_removal.h)
//   crease/fandisk/<n>                holes across n = 1, 2, 3 creases of the fandisk
// <size> is "small" (radius 2 % of the diagonal, below the structure size) or "large"
// (8 %, above it).
#pragma once

#include "core/case.h"
#include "generators/cad/cad_models.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace holebench::generators {

struct CaseDescriptor {
  std::string id;           ///< stable id, e.g. "cad/fandisk/edge_convex/small"
  std::string family;       ///< "box", "brep", "cad", "solid", "file"
  std::string kind;         ///< e.g. "corner_ccc", "k3/inner"
  std::string description;  ///< one line for listings
};

struct CatalogOptions {
  std::filesystem::path cad_data_dir = default_cad_data_dir();
  bool include_cad = true;  ///< the CGAL data set (analysed on first use: a few seconds)
  std::vector<std::filesystem::path> user_meshes;  ///< files or folders
  PrepareOptions prepare;
  /// Families to list ("box", "brep", "solid", "cad", "crease", "file"); empty: all. Listing a
  /// family analyses its models, so leaving out the ones a selection cannot match saves time.
  /// make() works for any family regardless.
  std::vector<std::string> families;
};

/// A model the catalog could not use, with the reason (missing, open, non-manifold, ...).
struct SkippedModel {
  std::string name;
  std::string reason;
};

/// A note on a model the catalog read (its B-Rep faces sewn, a deflection retried).
struct ModelNote {
  std::string name;  ///< "file/<stem>"
  std::string note;
};

struct SizeClass {
  const char* name;
  double radius_rel_diag;
};
/// The hole sizes of punched cases, relative to the diagonal; the structure size for the
/// expected decision is 6 % of the diagonal.
const std::vector<SizeClass>& punch_size_classes();

class CaseCatalog {
 public:
  explicit CaseCatalog(CatalogOptions options = {});
  ~CaseCatalog();

  /// Every case, in a fixed order. Models that cannot be used are left out and listed in
  /// skipped().
  const std::vector<CaseDescriptor>& cases() const;
  const std::vector<SkippedModel>& skipped() const;
  /// The notes on the models listed (AnalysedModel::notes), in listing order.
  const std::vector<ModelNote>& model_notes() const;

  /// Generates case `id` with vertex noise `noise_percent` (% of 1 % of the diagonal) drawn
  /// from `seed`. The ground truth is always clean. Throws std::invalid_argument for an
  /// unknown id and InvalidInputError for a model that cannot be used.
  Case make(const std::string& id, std::uint64_t seed = 0, double noise_percent = 0.0) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Shorthands over a catalog with default options.
std::vector<CaseDescriptor> list_cases();
Case make_case(const std::string& id, std::uint64_t seed = 0, double noise_percent = 0.0);

}  // namespace holebench::generators
