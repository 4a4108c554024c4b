// SPDX-License-Identifier: BSD-3-Clause
// Issue 2 (kernel, geometries): geometry type names follow Kratos and unknown names get a suggestion.
#include <gtest/gtest.h>

#include <string>

#include "core/geometries/geometry_type.h"
#include "core/utilities/error.h"
#include "geometry_test_utilities.h"

namespace mc {

TEST(GeometryType, NamesRoundTrip) {
  for (GeometryType type : test::AllGeometryTypes())
    EXPECT_EQ(GeometryTypeFromName(GeometryTypeName(type)), type) << GeometryTypeName(type);
  EXPECT_STREQ(GeometryTypeName(GeometryType::Tetrahedra3D10), "Tetrahedra3D10");
  EXPECT_STREQ(GeometryTypeName(GeometryType::Quadrilateral2D9), "Quadrilateral2D9");
  EXPECT_STREQ(GeometryTypeName(GeometryType::Prism3D6), "Prism3D6");
}

TEST(GeometryType, UnknownNameSuggestsNearest) {
  try {
    GeometryTypeFromName("Tetrahedron3D4");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Tetrahedron3D4"), std::string::npos) << message;
    EXPECT_NE(message.find("Tetrahedra3D4"), std::string::npos) << message;
  }
}

}  // namespace mc
