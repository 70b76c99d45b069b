#include "geompm/mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <clocale>
#include <exception>

namespace geompm {

namespace {
std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}
}  // namespace

GmshSession::GmshSession() : lock_(gmsh_mutex()) {
  if (const char* locale = std::setlocale(LC_NUMERIC, nullptr)) numeric_locale_ = locale;
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  try {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 0);
  } catch (...) {
    gmsh::finalize();
    std::setlocale(LC_NUMERIC, numeric_locale_.c_str());
    throw;
  }
}

GmshSession::~GmshSession() {
  try {
    gmsh::finalize();
  } catch (...) {  // nothing sensible to do in a destructor; the next session re-initialises
  }
  if (!numeric_locale_.empty()) std::setlocale(LC_NUMERIC, numeric_locale_.c_str());
}

std::string current_exception_message() {
  try {
    throw;
  } catch (const std::string& message) {
    return message;
  } catch (const char* message) {
    return message;
  } catch (const std::exception& error) {
    return error.what();
  } catch (...) {
    return "unknown error";
  }
}

}  // namespace geompm
