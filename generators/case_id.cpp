#include "generators/case_id.h"

#include "core/split_text.h"

#include <vector>

namespace holebench::generators {

std::optional<CaseId> parse_case_id(const std::string& text) {
  const std::vector<std::string> parts = split_text(text, '/');
  CaseId id;
  id.text = text;
  id.family = parts[0];
  if (id.family == "box" && parts.size() == 2) {
    id.kind = CaseIdKind::Box;
    id.target = parts[1];
    return id;
  }
  if (id.family == "brep") {
    id.kind = CaseIdKind::Brep;
    return id;
  }
  if (id.family == "crease" && parts.size() == 3) {
    id.kind = CaseIdKind::Crease;
    id.model = parts[1];
    id.target = parts[2];
    return id;
  }
  if (id.family == "file" && (parts.size() == 4 || parts.size() == 5) && parts[2] == "hole") {
    id.kind = CaseIdKind::RealHole;
    id.model = parts[1];
    id.target = parts[3];
    id.size = parts.size() == 5 ? parts[4] : "";
    return id;
  }
  const bool punched_family = id.family == "solid" || id.family == "cad" || id.family == "file";
  if (!punched_family || parts.size() != 4)
    return std::nullopt;
  id.model = parts[1];
  if (id.family == "file" && parts[2] == "faces") {
    id.kind = CaseIdKind::FacesRemoved;
    id.target = parts[3];
    return id;
  }
  id.kind = CaseIdKind::Punched;
  id.target = parts[2];
  id.size = parts[3];
  return id;
}

}  // namespace holebench::generators
