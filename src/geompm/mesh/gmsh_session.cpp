#include "geompm/mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <exception>

namespace geompm {

namespace {
std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}
}  // namespace

GmshSession::GmshSession() : lock_(gmsh_mutex()) {
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  try {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 0);
  } catch (...) {
    gmsh::finalize();
    throw;
  }
}

GmshSession::~GmshSession() {
  try {
    gmsh::finalize();
  } catch (...) {  // nothing sensible to do in a destructor; the next session re-initialises
  }
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
