// SPDX-License-Identifier: BSD-3-Clause
#include "thermal/application/register_thermal.h"

#include <mutex>

#include "core/model/registry.h"
#include "thermal/elements/laplacian_element.h"

namespace mc {

void RegisterThermal() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const GeometryType type : {GeometryType::Triangle2D3, GeometryType::Quadrilateral2D4,
                                    GeometryType::Tetrahedra3D4, GeometryType::Hexahedra3D8}) {
      auto prototype = std::make_shared<const LaplacianElement>(0, Geometry(type, {}), nullptr);
      Registry<Element>::Instance().Add(prototype->Info(), prototype);
    }
  });
}

}  // namespace mc
