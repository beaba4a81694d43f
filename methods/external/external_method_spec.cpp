#include "methods/external/external_method_spec.h"

#include <stdexcept>

namespace holebench {

namespace {

constexpr const char* kFormat = "expected 'name=NAME;command=COMMAND'";

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char ch : text)
    quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

}  // namespace

void check_external_method_name(const std::string& name) {
  bool ok = !name.empty() && name[0] >= 'a' && name[0] <= 'z';
  for (char ch : name)
    ok = ok && ((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_');
  if (!ok) {
    throw std::invalid_argument("external method name '" + name +
                                "': use lower-case letters, digits and '_', starting with a "
                                "letter");
  }
}

void check_command_template(const std::string& command) {
  bool has_input = false, has_output = false;
  for (std::size_t open = command.find('{'); open != std::string::npos;
       open = command.find('{', open + 1)) {
    const auto close = command.find('}', open);
    const std::string placeholder =
        close == std::string::npos ? command.substr(open) : command.substr(open, close - open + 1);
    if (placeholder == "{input}") {
      has_input = true;
    } else if (placeholder == "{output}") {
      has_output = true;
    } else {
      throw std::invalid_argument("command '" + command + "': unknown placeholder '" + placeholder +
                                  "' (only {input} and {output})");
    }
  }
  if (!has_input || !has_output) {
    throw std::invalid_argument("command '" + command + "' must name {input} and {output}");
  }
}

ExternalMethodSpec parse_external_method_spec(const std::string& text) {
  ExternalMethodSpec spec;
  bool has_name = false, has_command = false;
  std::size_t start = 0;
  while (start < text.size()) {
    const auto equals = text.find('=', start);
    if (equals == std::string::npos)
      throw std::invalid_argument("'" + text + "': " + kFormat);
    const std::string key = trimmed(text.substr(start, equals - start));
    if (key == "command") {
      // The command runs to the end: a shell command may contain ';' itself.
      spec.command = trimmed(text.substr(equals + 1));
      has_command = true;
      break;
    }
    const auto semicolon = text.find(';', equals);
    const std::string value = trimmed(text.substr(
        equals + 1, semicolon == std::string::npos ? std::string::npos : semicolon - equals - 1));
    if (key == "name") {
      spec.name = value;
      has_name = true;
    } else if (key == "vertex_tolerance_rel_diag") {
      std::size_t used = 0;
      try {
        spec.vertex_tolerance_rel_diag = std::stod(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != value.size() || !(spec.vertex_tolerance_rel_diag >= 0.0))
        throw std::invalid_argument("'" + text + "': vertex_tolerance_rel_diag must be >= 0");
    } else {
      throw std::invalid_argument("'" + text + "': unknown key '" + key + "'; " + kFormat);
    }
    start = semicolon == std::string::npos ? text.size() : semicolon + 1;
  }
  if (!has_name)
    throw std::invalid_argument("'" + text + "': no name=; " + kFormat);
  if (!has_command || spec.command.empty())
    throw std::invalid_argument("'" + text + "': no command=; " + kFormat);
  check_external_method_name(spec.name);
  check_command_template(spec.command);
  return spec;
}

std::string expand_command(const std::string& command, const std::string& input,
                           const std::string& output) {
  std::string expanded;
  for (std::size_t i = 0; i < command.size();) {
    if (command.compare(i, 7, "{input}") == 0) {
      expanded += shell_quoted(input);
      i += 7;
    } else if (command.compare(i, 8, "{output}") == 0) {
      expanded += shell_quoted(output);
      i += 8;
    } else {
      expanded += command[i++];
    }
  }
  return expanded;
}

}  // namespace holebench
