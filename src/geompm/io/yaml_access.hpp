// Typed access to a parsed YAML document that remembers where every value came from (key path
// and line), so that each complaint about a value names the file, the key path and the line.
//
// Maps are opened with the list of keys they may hold and an unknown key is an error at once,
// with the closest allowed key suggested: a misspelt optional key ("intial") would otherwise be
// ignored silently and its default used. Duplicate keys are errors too (yaml-cpp keeps both and
// a lookup would see only the first). YAML merge keys ("<<: *defaults"), which yaml-cpp 0.7
// does not expand, are expanded here so that phases can share settings through anchors.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geompm/core/error.hpp"
#include "geompm/core/types.hpp"

namespace geompm::yaml {

/// The magnitudes a number of the model file may have (besides 0): wide enough for any quantity
/// in any consistent units (N-mm-t densities of 1e-9, moduli of 1e12 Pa), narrow enough that the
/// products a step forms stay far from overflow and underflow.
inline constexpr double largest_magnitude = 1e20;
inline constexpr double smallest_magnitude = 1e-20;

class Map;

/// One value of the document with the key path ("phases[1].gravity") and line that lead to it.
class Node {
 public:
  Node(YAML::Node node, std::string key_path, int line, std::shared_ptr<const std::string> file);

  const std::string& path() const { return path_; }
  int line() const { return line_; }
  SourceLocation where() const { return {*file_, path_, line_}; }
  /// Throws InputError at this value.
  [[noreturn]] void fail(const std::string& what) const;

  bool is_null() const { return node_.IsNull(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool is_list() const { return node_.IsSequence(); }
  bool is_map() const { return node_.IsMap(); }
  /// How the value looks, for messages: "'abc'", "the quoted text \"1\"", "a list", "a map".
  std::string describe() const;

  /// A finite number written without quotes, 0 or of a magnitude in [smallest_magnitude,
  /// largest_magnitude].
  double number() const;
  /// A whole number that fits an int.
  int integer() const;
  /// true or false (YAML also accepts yes/no, on/off).
  bool boolean() const;
  /// Any scalar, as written (numbers included: a name may be "1").
  std::string text() const;
  /// A scalar that is one of `allowed`; the message lists them and suggests the closest.
  std::string choice(const std::vector<std::string>& allowed) const;

  /// A list; the items' key paths are path[i].
  std::vector<Node> items() const;
  /// A list of exactly `dimension` numbers (2 or 3); z = 0 in 2D.
  Vec3 vector(int dimension) const;

  /// A map that may hold only `allowed_keys`.
  Map map(std::initializer_list<std::string_view> allowed_keys) const;
  /// A map whose keys the user chooses (names of materials, bodies; material parameters), in
  /// file order, merge keys expanded.
  std::vector<std::pair<std::string, Node>> entries() const;

 private:
  double finite_number() const;

  YAML::Node node_;
  std::string path_;
  int line_;
  std::shared_ptr<const std::string> file_;
};

/// A map opened with the keys it may hold.
class Map {
 public:
  Map(Node self, std::vector<std::pair<std::string, Node>> entries)
      : self_(std::move(self)), entries_(std::move(entries)) {}

  const Node& node() const { return self_; }
  bool has(std::string_view key) const { return find(key).has_value(); }
  std::optional<Node> find(std::string_view key) const;
  /// Like find, but a key with nothing after it counts as absent: for optional lists and
  /// sections whose entries may all have been commented out.
  std::optional<Node> find_non_empty(std::string_view key) const;
  /// The value of `key`; if absent, fails at this map's line with the key path of the key.
  Node required(std::string_view key) const;
  /// Fails unless exactly one of `keys` is present, and returns that key.
  std::string exactly_one_of(std::initializer_list<std::string_view> keys) const;

  double number_or(std::string_view key, double fallback) const;
  int integer_or(std::string_view key, int fallback) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  std::string text_or(std::string_view key, const std::string& fallback) const;

 private:
  Node self_;
  std::vector<std::pair<std::string, Node>> entries_;
};

/// Parses `text` (YAML or JSON); throws InputError with yaml-cpp's message and line for a
/// syntax error. The root's key path is empty and its line 1.
Node parse(const std::string& text, const std::string& file);

/// " (did you mean 'initial'?)" when a candidate is within a small edit distance of `found`,
/// else "".
std::string did_you_mean(std::string_view found, const std::vector<std::string>& candidates);

/// "a, b, c"
std::string join(const std::vector<std::string>& names);

}  // namespace geompm::yaml
