#include "harness/results/json_fields.h"

#include <cmath>
#include <stdexcept>

namespace holebench::harness {

std::string field_name(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string quote_json(const nlohmann::json& value) {
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > 60)
    text = text.substr(0, 57) + "...";
  return text;
}

namespace {

[[noreturn]] void refuse(const std::string& name, const std::string& what) {
  throw std::invalid_argument("field \"" + name + "\": " + what);
}

const nlohmann::json* find(const nlohmann::json& object, const char* key) {
  if (!object.is_object())
    return nullptr;
  const auto it = object.find(key);
  if (it == object.end() || it->is_null())
    return nullptr;
  return &*it;
}

template <typename T, typename Convert>
std::vector<T> list_field(const nlohmann::json& object, const std::string& parent, const char* key,
                          const std::vector<T>& fallback, Convert convert) {
  const nlohmann::json* value = find(object, key);
  if (!value)
    return fallback;
  const std::string name = field_name(parent, key);
  if (!value->is_array())
    refuse(name, "expected a list, got " + quote_json(*value));
  std::vector<T> list;
  for (std::size_t i = 0; i < value->size(); ++i)
    list.push_back(convert((*value)[i], name + "[" + std::to_string(i) + "]"));
  return list;
}

}  // namespace

void check_known_fields(const nlohmann::json& object, const std::string& parent,
                        const std::vector<std::string>& known) {
  if (!object.is_object())
    refuse(parent, "expected an object, got " + quote_json(object));
  for (const auto& [key, value] : object.items()) {
    bool listed = false;
    for (const auto& name : known)
      listed = listed || name == key;
    if (listed)
      continue;
    std::string names;
    for (const auto& name : known)
      names += (names.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown field \"" + field_name(parent, key) +
                                "\" (known: " + names + ")");
  }
}

double as_number(const nlohmann::json& value, const std::string& name) {
  if (!value.is_number())
    refuse(name, "expected a number, got " + quote_json(value));
  const double number = value.get<double>();
  if (!std::isfinite(number))
    refuse(name, "not a finite number");
  return number;
}

std::int64_t as_integer(const nlohmann::json& value, const std::string& name, std::int64_t min,
                        std::int64_t max) {
  if (value.is_number_unsigned()) {
    const auto number = value.get<std::uint64_t>();
    if (number > static_cast<std::uint64_t>(max) ||
        (min > 0 && number < static_cast<std::uint64_t>(min))) {
      refuse(name, quote_json(value) + " is outside [" + std::to_string(min) + ", " +
                       std::to_string(max) + "]");
    }
    return static_cast<std::int64_t>(number);
  }
  if (value.is_number_integer()) {
    const auto number = value.get<std::int64_t>();
    if (number < min || number > max) {
      refuse(name, quote_json(value) + " is outside [" + std::to_string(min) + ", " +
                       std::to_string(max) + "]");
    }
    return number;
  }
  if (value.is_number_float()) {
    const double number = value.get<double>();
    // Integral and in range (the bounds' doubles are exact enough for the check's purpose).
    if (std::isfinite(number) && number == std::floor(number) &&
        number >= static_cast<double>(min) && number <= static_cast<double>(max) &&
        std::fabs(number) < 9.0e15) {
      return static_cast<std::int64_t>(number);
    }
    refuse(name, "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                     "], got " + quote_json(value));
  }
  refuse(name, "expected an integer, got " + quote_json(value));
}

std::uint64_t as_unsigned(const nlohmann::json& value, const std::string& name) {
  if (value.is_number_unsigned())
    return value.get<std::uint64_t>();
  if (value.is_number_integer())
    refuse(name, quote_json(value) + " is negative");
  if (value.is_number_float()) {
    const double number = value.get<double>();
    if (std::isfinite(number) && number >= 0.0 && number == std::floor(number) && number < 9.0e15)
      return static_cast<std::uint64_t>(number);
    refuse(name, "expected a non-negative integer, got " + quote_json(value));
  }
  refuse(name, "expected a non-negative integer, got " + quote_json(value));
}

std::string as_string(const nlohmann::json& value, const std::string& name) {
  if (!value.is_string())
    refuse(name, "expected a string, got " + quote_json(value));
  return value.get<std::string>();
}

double number_field(const nlohmann::json& object, const std::string& parent, const char* key,
                    double fallback) {
  const nlohmann::json* value = find(object, key);
  return value ? as_number(*value, field_name(parent, key)) : fallback;
}

std::int64_t integer_field(const nlohmann::json& object, const std::string& parent, const char* key,
                           std::int64_t fallback, std::int64_t min, std::int64_t max) {
  const nlohmann::json* value = find(object, key);
  return value ? as_integer(*value, field_name(parent, key), min, max) : fallback;
}

std::uint64_t unsigned_field(const nlohmann::json& object, const std::string& parent,
                             const char* key, std::uint64_t fallback) {
  const nlohmann::json* value = find(object, key);
  return value ? as_unsigned(*value, field_name(parent, key)) : fallback;
}

bool bool_field(const nlohmann::json& object, const std::string& parent, const char* key,
                bool fallback) {
  const nlohmann::json* value = find(object, key);
  if (!value)
    return fallback;
  if (!value->is_boolean())
    refuse(field_name(parent, key), "expected true or false, got " + quote_json(*value));
  return value->get<bool>();
}

std::string string_field(const nlohmann::json& object, const std::string& parent, const char* key,
                         const std::string& fallback) {
  const nlohmann::json* value = find(object, key);
  return value ? as_string(*value, field_name(parent, key)) : fallback;
}

std::vector<std::string> string_list_field(const nlohmann::json& object, const std::string& parent,
                                           const char* key,
                                           const std::vector<std::string>& fallback) {
  return list_field<std::string>(object, parent, key, fallback, as_string);
}

std::vector<double> number_list_field(const nlohmann::json& object, const std::string& parent,
                                      const char* key, const std::vector<double>& fallback) {
  return list_field<double>(object, parent, key, fallback, as_number);
}

std::vector<std::uint64_t> unsigned_list_field(const nlohmann::json& object,
                                               const std::string& parent, const char* key,
                                               const std::vector<std::uint64_t>& fallback) {
  return list_field<std::uint64_t>(object, parent, key, fallback, as_unsigned);
}

}  // namespace holebench::harness

namespace holebench::harness {
namespace {

// A SAX pass that only tracks where it is: the path of the value being read when the
// parser stops at an error.
class PathTracker : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string path() const {
    std::string text;
    for (std::size_t i = 0; i < levels_.size(); ++i) {
      const Level& level = levels_[i];
      if (level.array) {
        // The innermost array's failing element is the next one; an outer array's is the
        // one being read.
        const std::size_t index = i + 1 == levels_.size() ? level.count : level.count - 1;
        text += "[" + std::to_string(index) + "]";
      } else if (level.has_key) {
        text += (text.empty() ? "" : ".") + level.key;
      }
    }
    return text.empty() ? "(top level)" : text;
  }
  std::string error;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    value();
    levels_.push_back({false, 0, {}, false});
    return true;
  }
  bool key(string_t& key) override {
    levels_.back().key = key;
    levels_.back().has_key = true;
    return true;
  }
  bool end_object() override {
    levels_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    value();
    levels_.push_back({true, 0, {}, false});
    return true;
  }
  bool end_array() override {
    levels_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    error = e.what();
    return false;
  }

 private:
  struct Level {
    bool array = false;
    std::size_t count = 0;  ///< elements started (arrays)
    std::string key;        ///< the key being read (objects)
    bool has_key = false;
  };
  bool value() {
    if (!levels_.empty() && levels_.back().array)
      ++levels_.back().count;
    return true;
  }
  std::vector<Level> levels_;
};

}  // namespace

nlohmann::json parse_json_naming_field(const std::string& text) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    PathTracker tracker;
    try {
      nlohmann::json::sax_parse(text, &tracker);
    } catch (const std::exception&) {
    }
    std::string what = e.what();
    // "[json.exception.parse_error.101] parse error at line 1, ..." -> "parse error at ..."
    if (const auto end = what.find("] "); what.rfind("[json.exception", 0) == 0 && end != what.npos)
      what = what.substr(end + 2);
    throw std::invalid_argument("field \"" + tracker.path() + "\": not valid JSON: " + what);
  }
}

}  // namespace holebench::harness
