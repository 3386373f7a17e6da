#pragma once
// Strict, located reading of a JSON document: every value knows its JSON pointer, every
// object declares the keys it takes, and every mistake becomes rt::Error
// "FILE: /objects/3/radius: must be > 0, got -1".

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "core/ray.h"

namespace rt {

// Reads and parses a JSON file (comments allowed); syntax errors name line and column.
nlohmann::json parse_json_file(const std::filesystem::path& path);

class JsonValue {
  public:
    JsonValue(const nlohmann::json& json, std::string pointer, const std::string& file)
        : json_(&json), pointer_(std::move(pointer)), file_(&file) {}

    const std::string& pointer() const { return pointer_; }
    const std::string& file() const { return *file_; }
    const nlohmann::json& raw() const { return *json_; }
    [[noreturn]] void fail(const std::string& what) const;

    // Objects. keys() fails on a non-object or on a key outside `allowed`.
    void keys(std::initializer_list<std::string_view> allowed) const;
    bool has(std::string_view key) const;
    JsonValue operator[](std::string_view key) const;  // a required key
    std::optional<JsonValue> find(std::string_view key) const;
    std::vector<std::pair<std::string, JsonValue>> members() const;

    // Arrays, with their allowed length.
    std::vector<JsonValue> elements(std::size_t min_size = 0,
                                    std::size_t max_size = SIZE_MAX) const;

    // Scalars; every number must be finite and fit a float.
    float number() const;
    float number_at_least(float lo) const;
    float number_above(float lo) const;
    float number_between(float lo, float hi) const;
    int integer_between(int lo, int hi) const;
    bool boolean() const;
    std::string string() const;
    vec3 vector3() const;          // [x, y, z]
    double number_double() const;  // as number(), without the rounding to float
    glm::dvec3 dvector3() const;   // as vector3(), without the rounding to float
    vec3 colour() const;           // [r, g, b] or one grey number, each >= 0

    bool is_array() const { return json_->is_array(); }
    bool is_object() const { return json_->is_object(); }
    bool is_number() const { return json_->is_number(); }
    bool is_string() const { return json_->is_string(); }

  private:
    std::string describe_type() const;

    const nlohmann::json* json_;
    std::string pointer_;
    const std::string* file_;
};

}  // namespace rt
