// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace mc {

/// Every geometry the kernel knows. Names follow Kratos (Line2D2 = line of 2 nodes in a 2D
/// working space; Tetrahedra3D4 keeps Kratos' plural).
enum class GeometryType {
  Point2D,
  Point3D,
  Line2D2,
  Line2D3,
  Line3D2,
  Line3D3,
  Triangle2D3,
  Triangle2D6,
  Quadrilateral2D4,
  Quadrilateral2D8,
  Quadrilateral2D9,
  Triangle3D3,
  Triangle3D6,
  Quadrilateral3D4,
  Quadrilateral3D8,
  Quadrilateral3D9,
  Tetrahedra3D4,
  Tetrahedra3D10,
  Hexahedra3D8,
  Hexahedra3D20,
  Hexahedra3D27,
  Prism3D6,
};

enum class GeometryFamily { Point, Line, Triangle, Quadrilateral, Tetrahedron, Hexahedron, Prism };

/// Which coordinates a geometric quantity is computed with.
enum class Configuration { Initial, Current };

const char* GeometryTypeName(GeometryType type);
/// Throws InputError with the nearest valid names.
GeometryType GeometryTypeFromName(const std::string& name);

}  // namespace mc
