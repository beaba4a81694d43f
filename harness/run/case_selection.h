// Selecting cases by id patterns: '*' matches any run of characters (also '/'), '?' one.
#pragma once

#include "generators/case_catalog.h"
#include "harness/run/case_pattern.h"

#include <string>
#include <vector>

namespace holebench::harness {

/// Prints each model the catalog skipped, with its reason, and each note on a model it read (a
/// B-Rep file's faces sewn, a deflection retried), to stderr.
void print_catalog_notes(const generators::CaseCatalog& catalog);

/// The catalog's cases matching any of `patterns`, in catalog order. An exact id or a
/// pattern that matches nothing is an error (std::invalid_argument), so that a typo never
/// silently runs nothing; except where it names a model the catalog skipped (a missing,
/// open, non-manifold or degenerate mesh: `catalog.skipped()` holds the reason, which the
/// commands print), so that the rest of the selection still runs.
std::vector<generators::CaseDescriptor> select_cases(const generators::CaseCatalog& catalog,
                                                     const std::vector<std::string>& patterns);

/// The default suite of `holebench run` (until named suites exist): the skeleton's box
/// holes, every synthetic B-Rep case, and the small holes of the procedural solids.
const std::vector<std::string>& default_case_patterns();

}  // namespace holebench::harness
