// XML text helpers shared by the .vtu and .pvd writers (internal to io/).
#pragma once

#include <string>

namespace geompm::vtk_xml {

/// Escapes the XML special characters, so that any field or file name makes a valid attribute.
inline std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace geompm::vtk_xml
