// Checked reading of one table of a TOML scene file: each getter checks the value's type and range
// where it reads it, and every error points at the offending key or value in the user's file.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "lancer/math/vec3.hpp"
#include "lancer/scene/scene_keys.hpp"
#include "lancer/scene/setting_checks.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// Characters (UTF-8 code points) in `text`.
std::size_t characterCount(std::string_view text);

// The allowed values of a number, and how a message says so.
struct NumberRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minExclusive = false;
  bool maxExclusive = false;
  bool nonZero = false;

  static NumberRange any() { return {}; }
  static NumberRange atLeast(double low) { return {low, std::numeric_limits<double>::infinity()}; }
  static NumberRange above(double low) { return {low, std::numeric_limits<double>::infinity(), true}; }
  static NumberRange between(double low, double high) { return {low, high}; }
  static NumberRange strictlyBetween(double low, double high) { return {low, high, true, true}; }
  static NumberRange nonZeroNumber() { return {.nonZero = true}; }

  bool contains(double value) const;
  std::string describe() const;  // "between 0 and 1", "> 0", "greater than 0 and less than 180", ...
};

// What an array of three numbers means, for messages: "[x, y, z]" or "[r, g, b]".
enum class Triple { Xyz, Rgb };

SourceLocation locate(const std::string& file, const toml::source_region& region);
// "string \"800\"", "integer 3", "floating-point number 1.5", "array of 2 values", "table", ...
std::string describeValue(const toml::node& node);
// "integer", "string", "floating-point number", "table", ...
std::string_view typeName(const toml::node& node);

class TomlTableReader {
 public:
  // `name` prefixes keys in messages ("render" -> "render.width"; "" for the document itself).
  // Throws InputError at the first key (in file order) that is not one of `kind`'s keys
  // (scene_keys.hpp).
  TomlTableReader(const toml::table& table, std::string name, const std::string& file, SceneTable kind);

  const toml::table& table() const { return table_; }
  const std::string& file() const { return file_; }
  const toml::node* find(std::string_view key) const { return table_.get(key); }
  std::string qualified(std::string_view key) const;
  // How messages name the table: "[render]", "[material.steel]", or "light[1]" for array elements.
  std::string label() const;
  SourceLocation location(const toml::node& node) const { return locate(file_, node.source()); }
  [[noreturn]] void fail(const toml::node& node, const std::string& message) const;
  // For keys that must be present: the message names the key and shows how to write it.
  [[noreturn]] void failMissing(std::string_view key, std::string_view example) const;

  std::optional<std::int64_t> integer(std::string_view key, std::int64_t min, std::int64_t max) const;
  // Any integer, for a setting a function of setting_checks.hpp checks (with settingName(key)).
  std::optional<std::int64_t> integer(std::string_view key) const;
  // The key's value's position and its name ("render.width"), for setting_checks.hpp.
  SettingName settingName(std::string_view key) const;
  std::optional<double> number(std::string_view key, NumberRange range = {}) const;
  std::optional<bool> boolean(std::string_view key) const;
  std::optional<std::string> string(std::string_view key) const;
  std::optional<std::string> nonEmptyString(std::string_view key) const;
  // A string drawn into the picture: at most `maxCharacters` characters (UTF-8 code points).
  std::optional<std::string> text(std::string_view key, std::size_t maxCharacters) const;
  // The index in `choices` of a string value; otherwise lists the choices (and the closest one).
  std::optional<int> choice(std::string_view key, std::span<const std::string_view> choices) const;
  std::optional<Vec3d> vector(std::string_view key, Triple meaning, NumberRange range = {}) const;
  // A number s (meaning [s, s, s]) or an array of three numbers.
  std::optional<Vec3d> numberOrVector(std::string_view key, Triple meaning, NumberRange range = {}) const;
  // A node that must be a vector (an element of an array of points), `name` how messages call it;
  // `alternative` names what else it may be ("a number or "), or is empty.
  Vec3d checkedVector(const toml::node& node, const std::string& name, Triple meaning,
                      const NumberRange& range, std::string_view alternative) const;

 private:
  double checkedNumber(const toml::node& node, const std::string& name, const NumberRange& range) const;

  const toml::table& table_;
  std::string name_;
  std::string file_;
};

}  // namespace lancer
