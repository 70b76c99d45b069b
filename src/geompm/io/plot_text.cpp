// Axis labels and the ASCII text of plots.
#include "geompm/io/plot_text.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <utility>

namespace geompm {

std::string default_axis_label(const std::vector<std::string>& columns, double scale) {
  std::string prefix;
  if (scale == -1.0)
    prefix = "-";
  else if (scale != 1.0)
    prefix = fmt::format("{:g} * ", scale);
  std::string label;
  for (const auto& column : columns) label += (label.empty() ? "" : ", ") + prefix + column;
  return label;
}

namespace {

// UTF-8 code points an engineer's label is likely to hold, and how they are written in ASCII.
const std::pair<char32_t, const char*> kSpelt[] = {
    {U'α', "alpha"}, {U'β', "beta"},  {U'γ', "gamma"},  {U'δ', "delta"}, {U'Δ', "Delta"},
    {U'ε', "eps"},   {U'θ', "theta"}, {U'λ', "lambda"}, {U'μ', "mu"},    {U'ν', "nu"},
    {U'π', "pi"},    {U'ρ', "rho"},   {U'σ', "sigma"},  {U'τ', "tau"},   {U'φ', "phi"},
    {U'ψ', "psi"},   {U'ω', "omega"}, {U'−', "-"},      {U'–', "-"},     {U'—', "-"},
    {U'×', "x"},     {U'·', "*"},     {U'²', "^2"},     {U'³', "^3"},    {U'°', " deg"},
    {U'≤', "<="},    {U'≥', ">="},    {U'±', "+-"},     {U'’', "'"},     {U'…', "..."},
};

// The code point starting at text[i] and the number of bytes it takes; a malformed sequence
// counts as one byte of U+FFFD.
std::pair<char32_t, std::size_t> decode(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t lead = byte(i);
  const std::size_t length = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc0 ? 2 : 1;
  if (length == 1 || i + length > text.size()) return {U'\uFFFD', 1};
  char32_t code = lead & (0x3f >> (length - 1));
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return {U'\uFFFD', 1};
    code = (code << 6) | (byte(i + k) & 0x3f);
  }
  return {code, length};
}

}  // namespace

std::string plot_ascii(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (static_cast<std::uint8_t>(text[i]) < 0x80) {
      out += text[i++];
      continue;
    }
    const auto [code, length] = decode(text, i);
    i += length;
    const char* spelt = "?";
    for (const auto& [from, to] : kSpelt)
      if (from == code) spelt = to;
    out += spelt;
  }
  return out;
}

}  // namespace geompm
