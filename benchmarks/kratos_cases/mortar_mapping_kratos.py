# SPDX-License-Identifier: BSD-3-Clause
"""Issue 13: Kratos 10.4's SimpleMortarMapperProcess on the shared mapper cases
(tests/cases/kratos_csma/integration_tests): T = z and DISPLACEMENT = (x, y, z) on the master part
Parts_Parts_Auto2, mapped with the default settings onto Parts_Parts_Auto1; the slave values are
stored in tests/cases/kratos_10_4/mortar_mapping.json for tests/python/test_mortar_mapping.py.

    $MORTARCONTACT_KRATOS_VENV/bin/python benchmarks/kratos_cases/mortar_mapping_kratos.py
"""
import json
import os

import KratosMultiphysics as KM
import KratosMultiphysics.StructuralMechanicsApplication  # registers MembraneElement3D3N/3D4N

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = os.path.join(ROOT, "tests", "cases", "kratos_csma", "integration_tests")
OUTPUT = os.path.join(ROOT, "tests", "cases", "kratos_10_4", "mortar_mapping.json")


def run(name):
    model = KM.Model()
    root = model.CreateModelPart("Structure", 2)
    root.ProcessInfo[KM.DOMAIN_SIZE] = 3
    for variable in (KM.DISPLACEMENT, KM.TEMPERATURE, KM.NORMAL):
        root.AddNodalSolutionStepVariable(variable)
    KM.ModelPartIO(os.path.join(CASES, name)).ReadModelPart(root)
    master, slave = root.GetSubModelPart("Parts_Parts_Auto2"), root.GetSubModelPart("Parts_Parts_Auto1")
    for node in master.Nodes:
        node.SetSolutionStepValue(KM.TEMPERATURE, node.Z)
        node.SetSolutionStepValue(KM.DISPLACEMENT, KM.Array3([node.X, node.Y, node.Z]))
    for variable in ("TEMPERATURE", "DISPLACEMENT"):
        settings = KM.Parameters(json.dumps({"origin_variable": variable}))
        KM.SimpleMortarMapperProcess(master, slave, settings).Execute()
    values = {}
    for node in slave.Nodes:
        u = node.GetSolutionStepValue(KM.DISPLACEMENT)
        values[str(node.Id)] = {"TEMPERATURE": node.GetSolutionStepValue(KM.TEMPERATURE), "DISPLACEMENT_X": u[0],
                                "DISPLACEMENT_Y": u[1], "DISPLACEMENT_Z": u[2]}
    return values


def main():
    KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
    cases = ("test_integration_triangle", "test_integration_quad")
    result = {"kratos": "10.4.4", **{name: run(name) for name in cases}}
    with open(OUTPUT, "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
        f.write("\n")


if __name__ == "__main__":
    main()
