// XML text helpers shared by the .vtu and .pvd writers (internal to io/).
#pragma once

#include <string>

namespace geompm::vtk_xml {

/// The component names of a symmetric tensor's six values, in ParaView's order: they make the
/// order explicit in ParaView's array lists.
inline constexpr const char* symmetric_tensor_components =
    " ComponentName0=\"XX\" ComponentName1=\"YY\" ComponentName2=\"ZZ\" "
    "ComponentName3=\"XY\" ComponentName4=\"YZ\" ComponentName5=\"XZ\"";

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
