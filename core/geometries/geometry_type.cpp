// SPDX-License-Identifier: BSD-3-Clause
#include "core/geometries/geometry_type.h"

#include <array>
#include <string_view>
#include <vector>

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {
namespace {

// Indexed by the enum value; the order must follow the enum declaration.
constexpr std::array<const char*, 22> kNames = {
    "Point2D",      "Point3D",          "Line2D2",          "Line2D3",          "Line3D2",          "Line3D3",
    "Triangle2D3",  "Triangle2D6",      "Quadrilateral2D4", "Quadrilateral2D8", "Quadrilateral2D9", "Triangle3D3",
    "Triangle3D6",  "Quadrilateral3D4", "Quadrilateral3D8", "Quadrilateral3D9", "Tetrahedra3D4",    "Tetrahedra3D10",
    "Hexahedra3D8", "Hexahedra3D20",    "Hexahedra3D27",    "Prism3D6",
};
static_assert(static_cast<std::size_t>(GeometryType::Prism3D6) + 1 == kNames.size());

}  // namespace

const char* GeometryTypeName(GeometryType type) { return kNames[static_cast<std::size_t>(type)]; }

GeometryType GeometryTypeFromName(const std::string& name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (name == kNames[i]) return static_cast<GeometryType>(i);
  const std::vector<std::string> candidates(kNames.begin(), kNames.end());
  throw InputError(Concat("unknown geometry type '", name, "'", DidYouMean(name, candidates)));
}

}  // namespace mc
