// Escaping text for XML and HTML (JUnit files, the report and the gallery pages).
#pragma once

#include <string>

namespace holebench::harness {

/// Escapes text for XML or HTML content (attribute = false) and attribute values
/// (attribute = true); characters XML 1.0 cannot hold (control characters other than tab,
/// newline, carriage return) become '?'.
std::string xml_escape(const std::string& text, bool attribute = false);

}  // namespace holebench::harness
