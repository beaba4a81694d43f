#include "methods/method_options.h"

#include <utility>

namespace holebench {

bool operator==(const MethodOption& a, const MethodOption& b) {
  return a.name == b.name && a.value == b.value;
}

MethodOptions& MethodOptions::add(const std::string& name, bool value) {
  values_.push_back({name, value});
  return *this;
}

MethodOptions& MethodOptions::add(const std::string& name, int value) {
  values_.push_back({name, static_cast<std::int64_t>(value)});
  return *this;
}

MethodOptions& MethodOptions::add(const std::string& name, unsigned value) {
  values_.push_back({name, static_cast<std::int64_t>(value)});
  return *this;
}

MethodOptions& MethodOptions::add(const std::string& name, std::int64_t value) {
  values_.push_back({name, value});
  return *this;
}

MethodOptions& MethodOptions::add(const std::string& name, double value) {
  values_.push_back({name, value});
  return *this;
}

MethodOptions& MethodOptions::add(const std::string& name, std::string value) {
  values_.push_back({name, std::move(value)});
  return *this;
}

MethodOptions& MethodOptions::add(const std::string& name, const char* value) {
  return add(name, std::string(value));
}

MethodOptions& MethodOptions::add(const std::string& name, const MethodOptions& nested) {
  for (const auto& option : nested.values())
    values_.push_back({name + "." + option.name, option.value});
  return *this;
}

const MethodOptionValue* MethodOptions::find(const std::string& name) const {
  for (const auto& option : values_) {
    if (option.name == name)
      return &option.value;
  }
  return nullptr;
}

bool operator==(const MethodOptions& a, const MethodOptions& b) {
  if (a.values().size() != b.values().size())
    return false;
  for (const auto& option : a.values()) {
    const MethodOptionValue* other = b.find(option.name);
    if (!other || *other != option.value)
      return false;
  }
  return true;
}

}  // namespace holebench
