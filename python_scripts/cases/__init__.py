"""Generated cases in the Kratos input format (mdpa + ProjectParameters.json + materials.json):
``hertz``, the gmsh-meshed Hertz cylinder and sphere pressed onto a block, with their evaluation
against Hertz theory. Meshing needs gmsh (PyPI)."""
