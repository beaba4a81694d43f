// Typed fields of a JSON object, read with errors that name the field: what the suite reader
// and the results reader use, so that a hostile or damaged file (a string for a number, a
// number too large for its type, a NaN or an infinity, a key nobody reads) is a one-line error
// such as `"noise_percent[1]": -5 is negative` instead of an exception from the JSON library or
// a silent default.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace holebench::harness {

/// The dotted name of `key` below `parent` ("" for the top level): "tolerances.default".
std::string field_name(const std::string& parent, const std::string& key);

/// A short quote of a JSON value for error messages (at most ~60 characters).
std::string quote_json(const nlohmann::json& value);

/// Throws std::invalid_argument "unknown field \"NAME\" (known: ...)" for a key of `object`
/// that is not among `known`. Unknown fields are refused where a typo would silently change
/// what runs (suites).
void check_known_fields(const nlohmann::json& object, const std::string& parent,
                        const std::vector<std::string>& known);

/// The value of `key` in `object` as the type named, or `fallback` when the key is missing
/// (or null where `null_is_missing`). Each throws std::invalid_argument naming the field when
/// the value is of another type or out of the type's range: numbers must be finite; integers
/// are integral and fit the type.
double number_field(const nlohmann::json& object, const std::string& parent, const char* key,
                    double fallback);
std::int64_t integer_field(const nlohmann::json& object, const std::string& parent, const char* key,
                           std::int64_t fallback, std::int64_t min, std::int64_t max);
std::uint64_t unsigned_field(const nlohmann::json& object, const std::string& parent,
                             const char* key, std::uint64_t fallback);
bool bool_field(const nlohmann::json& object, const std::string& parent, const char* key,
                bool fallback);
std::string string_field(const nlohmann::json& object, const std::string& parent, const char* key,
                         const std::string& fallback);

/// A value's conversions, naming `name` (the field) on error.
double as_number(const nlohmann::json& value, const std::string& name);
std::int64_t as_integer(const nlohmann::json& value, const std::string& name, std::int64_t min,
                        std::int64_t max);
std::uint64_t as_unsigned(const nlohmann::json& value, const std::string& name);
std::string as_string(const nlohmann::json& value, const std::string& name);

/// Lists: an array of the type, each element checked ("NAME[i]" on error).
std::vector<std::string> string_list_field(const nlohmann::json& object, const std::string& parent,
                                           const char* key,
                                           const std::vector<std::string>& fallback);
std::vector<double> number_list_field(const nlohmann::json& object, const std::string& parent,
                                      const char* key, const std::vector<double>& fallback);
std::vector<std::uint64_t> unsigned_list_field(const nlohmann::json& object,
                                               const std::string& parent, const char* key,
                                               const std::vector<std::uint64_t>& fallback);

}  // namespace holebench::harness

namespace holebench::harness {

/// Parses JSON text; on a syntax error (a NaN or an infinity written as a bare word, a number
/// too large for a double, a file cut short) throws std::invalid_argument naming the field
/// being read ("results[3].metrics.hausdorff_rel_diag") and the line and column.
nlohmann::json parse_json_naming_field(const std::string& text);

}  // namespace holebench::harness
