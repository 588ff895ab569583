#include "lancer/scene/toml_table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "lancer/scene/suggest.hpp"

namespace lancer {
namespace {

// Long strings are cut in messages so one line stays readable.
std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  if (text.size() > kMaxShown) return fmt::format("\"{}...\"", text.substr(0, kMaxShown));
  return fmt::format("\"{}\"", text);
}

std::string_view tripleWords(Triple meaning) { return meaning == Triple::Xyz ? "[x, y, z]" : "[r, g, b]"; }

bool isNumber(const toml::node& node) { return node.is_integer() || node.is_floating_point(); }

double numberValue(const toml::node& node) {
  if (const auto* integer = node.as_integer()) return static_cast<double>(integer->get());
  return node.as_floating_point()->get();
}

bool precedes(const toml::source_position& a, const toml::source_position& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

std::string joined(std::span<const std::string_view> words) {
  std::string result;
  for (std::string_view word : words) {
    if (!result.empty()) result += ", ";
    result += word;
  }
  return result;
}

}  // namespace

std::size_t characterCount(std::string_view text) {
  return static_cast<std::size_t>(std::count_if(
      text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xc0) != 0x80; }));
}

bool NumberRange::contains(double value) const {
  if (nonZero && value == 0) return false;
  if (minExclusive ? value <= min : value < min) return false;
  if (maxExclusive ? value >= max : value > max) return false;
  return true;
}

std::string NumberRange::describe() const {
  const bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
  std::string text;
  if (hasMin && hasMax) {
    if (!minExclusive && !maxExclusive)
      text = fmt::format("between {} and {}", min, max);
    else
      text = fmt::format("greater than {} and less than {}", min, max);
  } else if (hasMin) {
    text = fmt::format("{} {}", minExclusive ? ">" : ">=", min);
  } else if (hasMax) {
    text = fmt::format("{} {}", maxExclusive ? "<" : "<=", max);
  } else {
    text = "a finite number";
  }
  if (nonZero) text = hasMin || hasMax ? text + " and non-zero" : "non-zero";
  return text;
}

SourceLocation locate(const std::string& file, const toml::source_region& region) {
  return SourceLocation{file, static_cast<std::int64_t>(region.begin.line),
                        static_cast<std::int64_t>(region.begin.column), -1};
}

std::string_view typeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "floating-point number";
    case toml::node_type::boolean:
      return "boolean";
    case toml::node_type::array:
      return "array";
    case toml::node_type::table:
      return "table";
    case toml::node_type::date:
      return "date";
    case toml::node_type::time:
      return "time";
    case toml::node_type::date_time:
      return "date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

std::string describeValue(const toml::node& node) {
  if (const auto* text = node.as_string()) return fmt::format("string {}", quoted(text->get()));
  if (const auto* integer = node.as_integer()) return fmt::format("integer {}", integer->get());
  if (const auto* real = node.as_floating_point())
    return fmt::format("floating-point number {}", real->get());
  if (const auto* flag = node.as_boolean()) return fmt::format("boolean {}", flag->get());
  if (const auto* array = node.as_array()) {
    if (array->empty()) return "an empty array";
    return fmt::format("array of {} value{}", array->size(), array->size() == 1 ? "" : "s");
  }
  return std::string(typeName(node));
}

TomlTableReader::TomlTableReader(const toml::table& table, std::string name, const std::string& file,
                                 SceneTable kind)
    : table_(table), name_(std::move(name)), file_(file) {
  const std::span<const std::string_view> knownKeys = sceneKeys(kind);
  const toml::key* firstUnknown = nullptr;
  for (const auto& [key, value] : table_) {
    bool known = false;
    for (std::string_view candidate : knownKeys) known = known || key.str() == candidate;
    if (!known && (!firstUnknown || precedes(key.source().begin, firstUnknown->source().begin)))
      firstUnknown = &key;
  }
  if (!firstUnknown) return;
  const std::string where = name_.empty() ? std::string() : " in " + label();
  const std::string suggestion = didYouMean(firstUnknown->str(), knownKeys);
  const std::string message =
      suggestion.empty() ? fmt::format("unknown key '{}'{}; expected one of: {}", firstUnknown->str(), where,
                                       joined(knownKeys))
                         : fmt::format("unknown key '{}'{}{}", firstUnknown->str(), where, suggestion);
  throw InputError(locate(file_, firstUnknown->source()), message);
}

std::string TomlTableReader::label() const {
  return name_.find('[') == std::string::npos ? fmt::format("[{}]", name_) : name_;
}

std::string TomlTableReader::qualified(std::string_view key) const {
  return name_.empty() ? std::string(key) : fmt::format("{}.{}", name_, key);
}

void TomlTableReader::fail(const toml::node& node, const std::string& message) const {
  throw InputError(location(node), message);
}

void TomlTableReader::failMissing(std::string_view key, std::string_view example) const {
  throw InputError(location(table_), fmt::format("{} has no '{}'; add {}", label(), key, example));
}

std::optional<std::int64_t> TomlTableReader::integer(std::string_view key, std::int64_t min,
                                                     std::int64_t max) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  const std::string name = qualified(key);
  if (const auto* real = node->as_floating_point();
      real && std::isfinite(real->get()) && real->get() == std::floor(real->get()))
    fail(*node, fmt::format("{} must be an integer, found {}; write it without a decimal point", name,
                            describeValue(*node)));
  const auto* integer = node->as_integer();
  if (!integer) fail(*node, fmt::format("{} must be an integer, found {}", name, describeValue(*node)));
  if (integer->get() < min || integer->get() > max)
    fail(*node, fmt::format("{} must be between {} and {}, found {}", name, min, max, integer->get()));
  return integer->get();
}

std::optional<std::int64_t> TomlTableReader::integer(std::string_view key) const {
  return integer(key, std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max());
}

SettingName TomlTableReader::settingName(std::string_view key) const {
  const toml::node* node = find(key);
  return {node ? location(*node) : location(table_), qualified(key)};
}

double TomlTableReader::checkedNumber(const toml::node& node, const std::string& name,
                                      const NumberRange& range) const {
  if (!isNumber(node)) fail(node, fmt::format("{} must be a number, found {}", name, describeValue(node)));
  const double value = numberValue(node);
  if (!std::isfinite(value)) fail(node, fmt::format("{} must be a finite number, found {}", name, value));
  // The renderer holds scene values as floats: a larger magnitude would become infinite there.
  constexpr double kLargestFloat = std::numeric_limits<float>::max();
  if (std::abs(value) > kLargestFloat)
    fail(node, fmt::format("{} must be between -{:.7g} and {:.7g} (the range of a float), found {}", name,
                           kLargestFloat, kLargestFloat, value));
  if (!range.contains(value))
    fail(node, fmt::format("{} must be {}, found {}", name, range.describe(), value));
  return value;
}

std::optional<double> TomlTableReader::number(std::string_view key, NumberRange range) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  return checkedNumber(*node, qualified(key), range);
}

std::optional<bool> TomlTableReader::boolean(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  const auto* flag = node->as_boolean();
  if (!flag)
    fail(*node, fmt::format("{} must be true or false, found {}", qualified(key), describeValue(*node)));
  return flag->get();
}

std::optional<std::string> TomlTableReader::string(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  const auto* text = node->as_string();
  if (!text) fail(*node, fmt::format("{} must be a string, found {}", qualified(key), describeValue(*node)));
  return text->get();
}

std::optional<std::string> TomlTableReader::nonEmptyString(std::string_view key) const {
  std::optional<std::string> text = string(key);
  if (text && text->empty()) fail(*find(key), fmt::format("{} must not be empty", qualified(key)));
  return text;
}

std::optional<std::string> TomlTableReader::text(std::string_view key, std::size_t maxCharacters) const {
  std::optional<std::string> value = string(key);
  if (value && characterCount(*value) > maxCharacters)
    fail(*find(key), fmt::format("{} is {} characters long; at most {} are drawn", qualified(key),
                                 characterCount(*value), maxCharacters));
  return value;
}

std::optional<int> TomlTableReader::choice(std::string_view key,
                                           std::span<const std::string_view> choices) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  std::string quotedChoices;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    quotedChoices += i == 0 ? "" : (i + 1 == choices.size() ? " or " : ", ");
    quotedChoices += quoted(choices[i]);
  }
  const auto* text = node->as_string();
  if (!text)
    fail(*node, fmt::format("{} must be the string {}, found {}", qualified(key), quotedChoices,
                            describeValue(*node)));
  for (std::size_t i = 0; i < choices.size(); ++i)
    if (text->get() == choices[i]) return static_cast<int>(i);
  fail(*node, fmt::format("{} must be {}, found {}{}", qualified(key), quotedChoices, quoted(text->get()),
                          didYouMean(text->get(), choices)));
}

Vec3d TomlTableReader::checkedVector(const toml::node& node, const std::string& name, Triple meaning,
                                     const NumberRange& range, std::string_view alternative) const {
  const auto* array = node.as_array();
  if (!array || array->size() != 3)
    fail(node, fmt::format("{} must be {}an array of 3 numbers {}, found {}", name, alternative,
                           tripleWords(meaning), describeValue(node)));
  Vec3d result;
  for (int axis = 0; axis < 3; ++axis)
    result[axis] =
        checkedNumber(*array->get(static_cast<std::size_t>(axis)), fmt::format("{}[{}]", name, axis), range);
  return result;
}

std::optional<Vec3d> TomlTableReader::vector(std::string_view key, Triple meaning, NumberRange range) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  return checkedVector(*node, qualified(key), meaning, range, "");
}

std::optional<Vec3d> TomlTableReader::numberOrVector(std::string_view key, Triple meaning,
                                                     NumberRange range) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  if (isNumber(*node)) {
    const double value = checkedNumber(*node, qualified(key), range);
    return Vec3d{value, value, value};
  }
  return checkedVector(*node, qualified(key), meaning, range, "a number or ");
}

}  // namespace lancer
