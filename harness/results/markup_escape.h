// Escaping text for markup, one function per language: XML and HTML (JUnit files, the report
// and the gallery pages), Markdown table cells (compare, the summary and the leaderboard) and
// LaTeX (the report's tables).
#pragma once

#include <string>

namespace holebench::harness {

/// Escapes text for XML or HTML content (attribute = false) and attribute values
/// (attribute = true); characters XML 1.0 cannot hold (control characters other than tab,
/// newline, carriage return) become '?'.
std::string xml_escape(const std::string& text, bool attribute = false);

/// Text for a Markdown table cell: '|' becomes \|; a newline or carriage return (which
/// would end the row) becomes a space.
std::string markdown_cell(const std::string& text);

/// Escapes LaTeX's special characters (\\ & % $ # _ { } ~ ^).
std::string latex_escape(const std::string& text);

}  // namespace holebench::harness
