// The project's departures from the slice paper's steps (each an option, off by default) and
// the methods built from them: the named variants slice_loft_plus and slice_direct_plus (every
// departure), and the Table 2 ablation's methods (one departure each), run by name. The
// table in docs/slice_loft.md gives each departure's paper step, code and measured effect.
#pragma once

#include "methods/slice_loft/slice_loft.h"

#include <string>
#include <vector>

namespace holebench::slice_loft {

/// One departure from the paper: a name (used in method ids: slice_loft_with_<name>), what
/// it changes, and how it changes the options.
struct Departure {
  std::string name;
  std::string what;
  void (*apply)(SliceLoftOptions&);
};

/// The departures the project keeps, in the order docs/slice_loft.md lists them:
/// wide_sections (sections over the influencing area with a margin of at least 3 mean edges,
/// 2 slices beyond each end), both_end_tracing, major_axis (the slicing direction) and
/// plane_trimming (the portion's plane before the surface's domain).
const std::vector<Departure>& departures();

/// The options with every departure applied: what slice_loft ran by default before the
/// paper's steps became the default.
SliceLoftOptions plus_options(bool direct);

/// slice_loft_plus and slice_direct_plus: the named variants (every departure).
std::vector<SliceLoftMethod> named_variants();

/// The ablation's methods: slice_loft_with_<departure> and slice_direct_with_<departure>,
/// one departure each (Table 2 settled by ablation; suite slice_ablation).
std::vector<SliceLoftMethod> ablation_methods();

}  // namespace holebench::slice_loft
