"""Generated cases: ``hertz``, the gmsh-meshed Hertz cylinder and sphere pressed onto a block, with
their evaluation against Hertz theory, and ``mesh_files``, the one route from a generated mesh to
its files (a gmsh file with physical groups for mortarcontact, the mdpa made of it for Kratos).
Meshing needs gmsh (PyPI)."""
