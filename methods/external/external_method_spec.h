// An external method: any program that reads the holed mesh and writes the repaired one,
// named by a command template. "name=my_fill;command=python3 my_fill.py {input} {output}"
// on the command line (`holebench run --external`), {"name": ..., "command": ...} in a suite.
#pragma once

#include <string>
#include <vector>

namespace holebench {

struct ExternalMethodSpec {
  /// The method id in records and suites: lower-case letters, digits and '_', starting with
  /// a letter (e.g. "my_fill").
  std::string name;
  /// A shell command (run by /bin/sh -c in the directory holebench was started in) with the
  /// placeholders {input} (the holed mesh, binary PLY) and {output} (where the program writes
  /// the repaired mesh, PLY), each replaced by a quoted absolute path; no other {...}.
  std::string command;
  /// How far (relative to the holed input's bounding-box diagonal) an output vertex may lie
  /// from the input vertex it stands for; 0 (the default): the same position, bit for bit.
  /// For programs that store single-precision coordinates.
  double vertex_tolerance_rel_diag = 0.0;
  /// Programs that must be on PATH; where one is missing the job fails at once and says so
  /// (predefined methods only: a user's command reports a missing program by its exit code).
  std::vector<std::string> required_programs;
};

/// Parses "name=NAME;command=COMMAND", optionally with "vertex_tolerance_rel_diag=X;" before
/// the command; "command=" comes last and runs to the end (it may contain ';'). Throws
/// std::invalid_argument with a one-line reason: a missing or unknown key, a bad name, a bad
/// template (check_command_template).
ExternalMethodSpec parse_external_method_spec(const std::string& text);

/// Throws std::invalid_argument unless `name` is a valid method name (see `name`).
void check_external_method_name(const std::string& name);

/// Throws std::invalid_argument unless `command` contains {output} and {input}, and no other
/// placeholder ({...}).
void check_command_template(const std::string& command);

/// `command` with {input} and {output} replaced by the paths, single-quoted for the shell.
std::string expand_command(const std::string& command, const std::string& input,
                           const std::string& output);

}  // namespace holebench
