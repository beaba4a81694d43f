#include "harness/run/case_selection.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace holebench::harness {

namespace {

// Whether `pattern` could name cases of a model the catalog skipped: its first two segments
// ("cad/fandisk" of "cad/fandisk/*/small") match the model's "family/name".
bool names_a_skipped_model(const generators::CaseCatalog& catalog, const std::string& pattern) {
  const auto first = pattern.find('/');
  const auto second = first == std::string::npos ? first : pattern.find('/', first + 1);
  const std::string head = pattern.substr(0, second);
  for (const auto& skipped : catalog.skipped()) {
    if (wildcard_match(head, skipped.name))
      return true;
  }
  return false;
}

}  // namespace

void print_catalog_notes(const generators::CaseCatalog& catalog) {
  for (const auto& skipped : catalog.skipped()) {
    std::fprintf(stderr, "holebench: skipped model %s: %s\n", skipped.name.c_str(),
                 skipped.reason.c_str());
  }
  for (const auto& note : catalog.model_notes())
    std::fprintf(stderr, "holebench: model %s: %s\n", note.name.c_str(), note.note.c_str());
}

std::vector<generators::CaseDescriptor> select_cases(const generators::CaseCatalog& catalog,
                                                     const std::vector<std::string>& patterns) {
  const auto& all = catalog.cases();
  std::vector<char> chosen(all.size(), 0);
  for (const auto& pattern : patterns) {
    bool any = false;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (wildcard_match(pattern, all[i].id)) {
        chosen[i] = 1;
        any = true;
      }
    }
    if (!any && !names_a_skipped_model(catalog, pattern)) {
      throw std::invalid_argument("no case matches '" + pattern + "' (see `holebench cases list`)");
    }
  }
  std::vector<generators::CaseDescriptor> selected;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (chosen[i])
      selected.push_back(all[i]);
  }
  return selected;
}

const std::vector<std::string>& default_case_patterns() {
  static const std::vector<std::string> patterns = {"box/*", "brep/*", "solid/*/small"};
  return patterns;
}

}  // namespace holebench::harness
