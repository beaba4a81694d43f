// A method's settings as its records report them ("method_options" in results files), so
// that two runs of one method with different settings can be told apart. A method lists
// every field of its options struct, a nested struct's fields under its name
// ("crest_lines.jet_degree").
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace holebench {

/// A setting's value: a flag, a count, a number or a name (enumerations by their name).
using MethodOptionValue = std::variant<bool, std::int64_t, double, std::string>;

struct MethodOption {
  std::string name;
  MethodOptionValue value;
};

bool operator==(const MethodOption& a, const MethodOption& b);

/// The settings in the order the method lists them.
class MethodOptions {
 public:
  MethodOptions& add(const std::string& name, bool value);
  MethodOptions& add(const std::string& name, int value);
  MethodOptions& add(const std::string& name, unsigned value);
  MethodOptions& add(const std::string& name, std::int64_t value);
  MethodOptions& add(const std::string& name, double value);
  MethodOptions& add(const std::string& name, std::string value);
  MethodOptions& add(const std::string& name, const char* value);
  /// Every setting of `nested` under "name.".
  MethodOptions& add(const std::string& name, const MethodOptions& nested);

  const std::vector<MethodOption>& values() const { return values_; }
  bool empty() const { return values_.empty(); }
  /// The value of setting `name`, or nullptr.
  const MethodOptionValue* find(const std::string& name) const;

 private:
  std::vector<MethodOption> values_;
};

/// The same settings with the same values, in any order (a results file read back lists them
/// by name).
bool operator==(const MethodOptions& a, const MethodOptions& b);
inline bool operator!=(const MethodOptions& a, const MethodOptions& b) {
  return !(a == b);
}

}  // namespace holebench
