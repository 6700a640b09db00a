#include "sim/scenes/json_fields.h"

#include <cmath>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"

namespace topay {
namespace {

std::string TypeName(const nlohmann::json& value) { return value.type_name(); }

}  // namespace

nlohmann::json JsonFieldReader::ParseFile(std::size_t max_bytes, const std::string& what) const {
  return ParseText(ReadBoundedTextFile(file_, max_bytes, what));
}

nlohmann::json JsonFieldReader::ParseText(const std::string& text) const {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    throw ConfigError(file_, "", std::string("malformed JSON: ") + error.what());
  } catch (const nlohmann::json::exception& error) {  // e.g. a number out of double range
    throw ConfigError(file_, "", std::string("malformed JSON (number out of range): ") +
                                     error.what());
  }
}

std::string JsonFieldReader::Child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string JsonFieldReader::Index(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

void JsonFieldReader::RequireObject(const nlohmann::json& value,
                                    const std::string& path) const {
  if (!value.is_object()) Fail(path, "expected an object, got " + TypeName(value));
}

void JsonFieldReader::RequireArray(const nlohmann::json& value, const std::string& path) const {
  if (!value.is_array()) Fail(path, "expected an array, got " + TypeName(value));
}

const nlohmann::json& JsonFieldReader::Member(const nlohmann::json& object,
                                              const std::string& path,
                                              const std::string& key) const {
  const nlohmann::json* member = OptionalMember(object, key);
  if (member == nullptr) Fail(Child(path, key), "missing");
  return *member;
}

void JsonFieldReader::RequireKnownKeys(const nlohmann::json& object, const std::string& path,
                                       std::initializer_list<const char*> known) const {
  RequireObject(object, path);
  for (const auto& [key, value] : object.items()) {
    bool found = false;
    for (const char* name : known) found = found || key == name;
    if (!found) Fail(Child(path, key), "unknown field (misspelt?)");
  }
}

const nlohmann::json* JsonFieldReader::OptionalMember(const nlohmann::json& object,
                                                      const std::string& key) const {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

double JsonFieldReader::Number(const nlohmann::json& value, const std::string& path) const {
  if (!value.is_number()) Fail(path, "expected a number, got " + TypeName(value));
  const double number = value.get<double>();
  if (!std::isfinite(number)) Fail(path, "not a finite number");
  return number;
}

std::string JsonFieldReader::String(const nlohmann::json& value, const std::string& path) const {
  if (!value.is_string()) Fail(path, "expected a string, got " + TypeName(value));
  return value.get<std::string>();
}

std::uint64_t JsonFieldReader::Unsigned(const nlohmann::json& value,
                                        const std::string& path) const {
  if (!value.is_number_unsigned()) {
    if (value.is_number_integer()) Fail(path, "must not be negative");
    Fail(path, "expected a non-negative integer, got " + TypeName(value));
  }
  return value.get<std::uint64_t>();
}

Eigen::VectorXd JsonFieldReader::NumberArray(const nlohmann::json& value,
                                             const std::string& path, int size) const {
  RequireArray(value, path);
  if (size >= 0 && value.size() != static_cast<std::size_t>(size)) {
    Fail(path, "expected " + std::to_string(size) + " numbers, got " +
                   std::to_string(value.size()));
  }
  Eigen::VectorXd numbers(static_cast<Eigen::Index>(value.size()));
  for (std::size_t i = 0; i < value.size(); ++i) {
    numbers(static_cast<Eigen::Index>(i)) = Number(value[i], Index(path, i));
  }
  return numbers;
}

void JsonFieldReader::Fail(const std::string& path, const std::string& message) const {
  throw ConfigError(file_, path, message);
}

std::string JsonNumberText(double value) { return nlohmann::json(value).dump(); }

}  // namespace topay
