#include "geompm/io/yaml_access.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>

namespace geompm::yaml {

namespace {

std::string child_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

// yaml-cpp marks are 0-based and absent (-1) for some null values; fall back to the parent's line.
int line_of(const YAML::Node& node, int fallback) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() || mark.line < 0 ? fallback : mark.line + 1;
}

// A quoted scalar ("1000") has the non-specific tag "!", a plain one (1000) "?": a number or a
// boolean in quotes is text, and is rejected rather than guessed at.
bool is_quoted(const YAML::Node& node) { return node.Tag() == "!"; }

std::string where_in(const std::string& path) {
  return path.empty() ? "the model file's top level" : path;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

Node::Node(YAML::Node node, std::string key_path, int line, std::shared_ptr<const std::string> file)
    : node_(std::move(node)), path_(std::move(key_path)), line_(line), file_(std::move(file)) {}

void Node::fail(const std::string& what) const { throw InputError(where(), what); }

std::string Node::describe() const {
  if (!node_.IsDefined() || node_.IsNull()) return "nothing (an empty value)";
  if (node_.IsSequence()) return "a list";
  if (node_.IsMap()) return "a map";
  if (is_quoted(node_)) return "the quoted text \"" + node_.Scalar() + "\"";
  return "'" + node_.Scalar() + "'";
}

double Node::finite_number() const {
  double value = 0.0;
  if (!node_.IsScalar() || is_quoted(node_) || !YAML::convert<double>::decode(node_, value))
    fail("expected a number, found " + describe());
  if (!std::isfinite(value)) fail("expected a finite number, found " + describe());
  return value;
}

double Node::number() const {
  const double value = finite_number();
  // No quantity in any consistent units comes near these (docs/user-guide.md, "How values are
  // written"); beyond them, products in the arithmetic of a step overflow or underflow, and the
  // run would stop on a non-finite residual, far from the value at fault.
  const double magnitude = std::abs(value);
  if (magnitude > largest_magnitude || (value != 0 && magnitude < smallest_magnitude))
    fail(fmt::format("expected a number of magnitude between {:g} and {:g} (or 0), found {}",
                     smallest_magnitude, largest_magnitude, describe()));
  return value;
}

int Node::integer() const {
  const double value = finite_number();
  if (value != std::floor(value)) fail("expected a whole number, found " + describe());
  if (value < INT_MIN || value > INT_MAX)
    fail(fmt::format("expected a whole number between {} and {}, found {}", INT_MIN, INT_MAX,
                     describe()));
  return static_cast<int>(value);
}

bool Node::boolean() const {
  bool value = false;
  if (!node_.IsScalar() || is_quoted(node_) || !YAML::convert<bool>::decode(node_, value))
    fail("expected true or false, found " + describe());
  return value;
}

std::string Node::text() const {
  if (!node_.IsScalar()) fail("expected a single value (text), found " + describe());
  return node_.Scalar();
}

std::string Node::choice(const std::vector<std::string>& allowed) const {
  if (!node_.IsScalar())
    fail(fmt::format("expected one of: {}; found {}", join(allowed), describe()));
  const std::string value = node_.Scalar();
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
    fail(fmt::format("expected one of: {}; found '{}'{}", join(allowed), value,
                     did_you_mean(value, allowed)));
  return value;
}

std::vector<Node> Node::items() const {
  if (!node_.IsSequence()) fail("expected a list, found " + describe());
  std::vector<Node> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    const YAML::Node item = node_[i];
    out.emplace_back(item, fmt::format("{}[{}]", path_, i), line_of(item, line_), file_);
  }
  return out;
}

Vec3 Node::vector(int dimension) const {
  const char* layout = dimension == 3 ? "[x, y, z]" : "[x, y]";
  if (!node_.IsSequence())
    fail(fmt::format("expected a list of {} numbers {}, found {}", dimension, layout, describe()));
  if (static_cast<int>(node_.size()) != dimension)
    fail(fmt::format("expected a list of {} numbers {} (the model is {}D), found {} numbers",
                     dimension, layout, dimension, node_.size()));
  Vec3 v = Vec3::Zero();
  const std::vector<Node> components = items();
  for (int i = 0; i < dimension; ++i) v[i] = components[i].number();
  return v;
}

std::vector<std::pair<std::string, Node>> Node::entries() const {
  if (!node_.IsMap()) fail("expected a map (key: value, ...), found " + describe());
  std::vector<std::pair<std::string, Node>> own;
  std::vector<std::pair<std::string, Node>> merged;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const int key_line = line_of(it->first, line_);
    if (!it->first.IsScalar())
      Node(it->first, path_, key_line, file_).fail("expected a key name, found a map or list");
    const std::string key = it->first.Scalar();
    if (key == "<<" && !is_quoted(it->first)) {
      // A merge key: the entries of the aliased map(s), unless given here too.
      const YAML::Node source = it->second;
      std::vector<YAML::Node> sources;
      if (source.IsSequence())
        for (const YAML::Node& s : source) sources.push_back(s);
      else
        sources.push_back(source);
      for (const YAML::Node& s : sources)
        for (auto& entry : Node(s, path_, key_line, file_).entries()) merged.push_back(entry);
      continue;
    }
    Node value(it->second, child_path(path_, key), key_line, file_);
    for (const auto& [seen, first] : own)
      if (seen == key)
        value.fail(fmt::format("the key '{}' appears twice in {} (first at line {})", key,
                               where_in(path_), first.line()));
    own.emplace_back(key, value);
  }
  for (auto& entry : merged) {
    const auto same_key = [&](const auto& e) { return e.first == entry.first; };
    if (std::none_of(own.begin(), own.end(), same_key)) own.push_back(entry);
  }
  return own;
}

Map Node::map(std::initializer_list<std::string_view> allowed_keys) const {
  std::vector<std::pair<std::string, Node>> found = entries();
  std::vector<std::string> allowed(allowed_keys.begin(), allowed_keys.end());
  for (const auto& [key, value] : found)
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      value.fail(fmt::format("unknown key '{}' in {}{}; allowed keys: {}", key, where_in(path_),
                             did_you_mean(key, allowed), join(allowed)));
  return Map(*this, std::move(found));
}

std::optional<Node> Map::find(std::string_view key) const {
  for (const auto& [name, value] : entries_)
    if (name == key) return value;
  return std::nullopt;
}

std::optional<Node> Map::find_non_empty(std::string_view key) const {
  std::optional<Node> value = find(key);
  if (value && value->is_null()) return std::nullopt;
  return value;
}

Node Map::required(std::string_view key) const {
  if (auto value = find(key)) return *value;
  SourceLocation where = self_.where();
  where.key_path = child_path(self_.path(), key);
  throw InputError(where,
                   fmt::format("missing required key '{}' in {}", key, where_in(self_.path())));
}

std::string Map::exactly_one_of(std::initializer_list<std::string_view> keys) const {
  std::vector<std::string> names(keys.begin(), keys.end());
  std::optional<Node> first;
  std::string first_key;
  for (const std::string& key : names) {
    const std::optional<Node> value = find(key);
    if (!value) continue;
    if (first)
      value->fail(fmt::format("give only one of {} in {}; found both '{}' (line {}) and '{}'",
                              join(names), where_in(self_.path()), first_key, first->line(), key));
    first = value;
    first_key = key;
  }
  if (!first)
    self_.fail(
        fmt::format("expected one of the keys {} in {}", join(names), where_in(self_.path())));
  return first_key;
}

double Map::number_or(std::string_view key, double fallback) const {
  const std::optional<Node> value = find(key);
  return value ? value->number() : fallback;
}

int Map::integer_or(std::string_view key, int fallback) const {
  const std::optional<Node> value = find(key);
  return value ? value->integer() : fallback;
}

bool Map::boolean_or(std::string_view key, bool fallback) const {
  const std::optional<Node> value = find(key);
  return value ? value->boolean() : fallback;
}

std::string Map::text_or(std::string_view key, const std::string& fallback) const {
  const std::optional<Node> value = find(key);
  return value ? value->text() : fallback;
}

Node parse(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    const bool located = !e.mark.is_null() && e.mark.line >= 0;
    std::string what = "YAML syntax error: " + e.msg;
    if (located) what += fmt::format(" (column {})", e.mark.column + 1);
    throw InputError(SourceLocation{file, "", located ? e.mark.line + 1 : 0}, what);
  }
  // The root's line (where its first key is) is where a missing top-level section is reported.
  return Node(root, "", line_of(root, 1), std::make_shared<const std::string>(file));
}

std::string did_you_mean(std::string_view found, const std::vector<std::string>& candidates) {
  // Short names are close to many others ("x" and "y"): allow fewer edits for them.
  const std::size_t allowed_edits = found.size() <= 4 ? 1 : (found.size() <= 8 ? 2 : 3);
  std::size_t best = allowed_edits + 1;
  std::string best_name;
  for (const std::string& candidate : candidates) {
    const std::size_t d = edit_distance(found, candidate);
    if (d < best) {
      best = d;
      best_name = candidate;
    }
  }
  return best_name.empty() ? "" : " (did you mean '" + best_name + "'?)";
}

std::string join(const std::vector<std::string>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace geompm::yaml
