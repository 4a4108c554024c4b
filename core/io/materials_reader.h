// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace mc {

class Model;
class Parameters;

/// Applies a Kratos materials file (`*_materials.json`, spec 1.8) to the model:
///   {"properties": [{"model_part_name": "Structure.Parts_Solid", "properties_id": 1,
///     "Material": {"name": ..., "constitutive_law": {"name": "LinearElastic3DLaw"},
///                  "Variables": {"YOUNG_MODULUS": 2.1e11, ...},
///                  "Tables": {"t": {"input_variable": ..., "output_variable": ..., "data": [[x, y], ...]}}},
///     "sub_properties": [...]}]}
/// For each entry the properties `properties_id` are created in the root (and listed in the
/// named part), get a clone of the registered constitutive law and the variables typed by their
/// registered type (an Array3 from a 3-vector), and are assigned to every element and condition
/// of the part, replacing the property ids of the mdpa file.
/// `model_part_name` is a dotted path resolved by Model::GetModelPart; mapping legacy bare names
/// is the caller's job (spec 1.6). `sub_properties` are not supported: they are skipped with a
/// warning. Unknown keys, variables, laws and model parts are InputErrors that quote `origin`,
/// the key path and the nearest valid names.
void ReadMaterials(Model& model, const Parameters& materials, const std::string& origin);

}  // namespace mc
