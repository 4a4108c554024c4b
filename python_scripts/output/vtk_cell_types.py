"""Kratos geometries as meshio (VTK) cell types, and the node orders that differ; shared by the
VTU writer and the meshio mesh input (no meshio import here)."""

#: Kratos geometry name -> meshio (VTK) cell type
VTK_CELL_TYPES = {
    "Point2D": "vertex", "Point3D": "vertex",
    "Line2D2": "line", "Line3D2": "line", "Line2D3": "line3", "Line3D3": "line3",
    "Triangle2D3": "triangle", "Triangle3D3": "triangle", "Triangle2D6": "triangle6", "Triangle3D6": "triangle6",
    "Quadrilateral2D4": "quad", "Quadrilateral3D4": "quad", "Quadrilateral2D8": "quad8",
    "Quadrilateral3D8": "quad8", "Quadrilateral2D9": "quad9", "Quadrilateral3D9": "quad9",
    "Tetrahedra3D4": "tetra", "Tetrahedra3D10": "tetra10",
    "Hexahedra3D8": "hexahedron", "Hexahedra3D20": "hexahedron20", "Hexahedra3D27": "hexahedron27",
    "Prism3D6": "wedge",
}

# Our hexahedra list the vertical mid-edges before the top ones and the face centres as bottom,
# front, right, back, left, top; VTK lists top edges first and faces as left, right, front, back,
# bottom, top. Column k of the VTK cell takes our node VTK_NODE_ORDER[k].
_HEX27_TO_VTK = [*range(12), 16, 17, 18, 19, 12, 13, 14, 15, 24, 22, 21, 23, 20, 25, 26]
VTK_NODE_ORDER = {"hexahedron20": _HEX27_TO_VTK[:20], "hexahedron27": _HEX27_TO_VTK}
