// Bad parameters of the soil models are reported as a ParameterError naming the key.
#include <gtest/gtest.h>

#include <algorithm>

#include "geompm/core/error.hpp"
#include "geompm/materials/material.hpp"

namespace geompm {
namespace {

std::string error_key(const std::string& model, const ParameterMap& p) {
  try {
    create_material(model, p);
  } catch (const ParameterError& e) {
    return e.key();
  }
  return "(no error)";
}

const ParameterMap sand = {{"c", 2}, {"phi", 32}, {"psi", 5}, {"E", 2e4}, {"nu", 0.3}};
const ParameterMap clay = {{"E_over_su", 500}, {"nu", 0.49}, {"su", 10}};

ParameterMap with(ParameterMap p, const std::string& key, double value) {
  p[key] = value;
  return p;
}
ParameterMap without(ParameterMap p, const std::string& key) {
  p.erase(key);
  return p;
}

TEST(SoilParameters, BothModelsAreRegistered) {
  const auto names = material_models();
  EXPECT_NE(std::find(names.begin(), names.end(), "tresca"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "mohr_coulomb"), names.end());
  EXPECT_EQ(create_material("mohr_coulomb", sand)->model_name(), std::string("mohr_coulomb"));
  EXPECT_EQ(create_material("tresca", clay)->model_name(), std::string("tresca"));
  EXPECT_EQ(create_material("tresca", clay)->reference_modulus(), 5000);
}

TEST(SoilParameters, MohrCoulombRanges) {
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "phi", -1)), "phi");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "phi", 90)), "phi");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "psi", 33)), "psi");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "psi", -1)), "psi");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "c", -1)), "c");
  EXPECT_EQ(error_key("mohr_coulomb", with(with(with(sand, "c", 0), "phi", 0), "psi", 0)), "c");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "E", 0)), "E");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "nu", 0.5)), "nu");
  EXPECT_EQ(error_key("mohr_coulomb", without(sand, "phi")), "phi");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "cohesion", 1)), "cohesion");
  // The cut-off may not lie beyond the apex c / tan(phi) = 3.2 nor below zero.
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "tension_cutoff", 3.3)), "tension_cutoff");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "tension_cutoff", -1)), "tension_cutoff");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "tension_cutoff", 1)), "(no error)");
  EXPECT_EQ(error_key("mohr_coulomb", sand), "(no error)");
  EXPECT_EQ(error_key("mohr_coulomb", without(sand, "psi")), "(no error)");  // psi = 0
  // docs/materials.md §1.7: 0 elastic, 1 plastic (the model reader's numbers for the words).
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "surface_tangent", 1)), "(no error)");
  EXPECT_EQ(error_key("mohr_coulomb", with(sand, "surface_tangent", 2)), "surface_tangent");
}

TEST(SoilParameters, TrescaRanges) {
  EXPECT_EQ(error_key("tresca", with(clay, "su", 0)), "su");
  EXPECT_EQ(error_key("tresca", with(clay, "su", -3)), "su");
  EXPECT_EQ(error_key("tresca", without(clay, "su")), "su");
  EXPECT_EQ(error_key("tresca", with(clay, "su_gradient", 1.5)), "su_reference_level");
  EXPECT_EQ(error_key("tresca", with(with(clay, "su_gradient", 1.5), "su_reference_level", 0)),
            "(no error)");
  EXPECT_EQ(error_key("tresca", with(clay, "E", 3000)), "E");       // both E and E_over_su
  EXPECT_EQ(error_key("tresca", without(clay, "E_over_su")), "E");  // neither
  EXPECT_EQ(error_key("tresca", with(clay, "E_over_su", -2)), "E_over_su");
  EXPECT_EQ(error_key("tresca", with(clay, "su_min", 0)), "su_min");
  EXPECT_EQ(error_key("tresca", with(clay, "nu", 0.5)), "nu");
  EXPECT_EQ(error_key("tresca", with(clay, "phi", 0)), "phi");  // unknown key
  EXPECT_EQ(error_key("tresca", with(clay, "surface_tangent", 0)), "(no error)");
  EXPECT_EQ(error_key("tresca", with(clay, "surface_tangent", 0.5)), "surface_tangent");
  EXPECT_EQ(error_key("tresca", clay), "(no error)");
}

}  // namespace
}  // namespace geompm
