"""Model-part names as written in Kratos inputs (spec 1.6).

- ``"Structure"``: a root model part;
- ``"Structure.DISPLACEMENT_Displacement_Auto1"``: dotted full path;
- ``"DISPLACEMENT_BC_rolling_x"`` (legacy bare name): searched in every sub model part of every
  root, recursively; several matches are an InputError listing them;
- ``"Structure.computing_domain"`` (legacy, no longer created): the root itself, unless a part
  of that name really exists.
"""
from __future__ import annotations

from .. import _core
from ..utilities import nearest

_LEGACY_ROOT_ALIASES = ("computing_domain",)


def _all_parts(model):
    stack = [model.GetModelPart(name) for name in model.ModelPartNames()]
    while stack:
        part = stack.pop()
        yield part
        stack.extend(part.SubModelParts)


def resolve_model_part(model, name: str):
    """The model part that ``name`` designates (see the module docstring)."""
    if not isinstance(name, str) or not name:
        raise _core.InputError(f"model_part_name must be a non-empty string, got {name!r}")
    if model.HasModelPart(name):
        return model.GetModelPart(name)
    root_name, _, rest = name.partition(".")
    if rest and rest in _LEGACY_ROOT_ALIASES and model.HasModelPart(root_name):
        return model.GetModelPart(root_name)
    if not rest:
        matches = [part for part in _all_parts(model) if part.Name == name and part.IsSubModelPart()]
        if len(matches) == 1:
            return matches[0]
        if len(matches) > 1:
            listed = ", ".join(sorted(part.FullName() for part in matches))
            raise _core.InputError(f"model part name '{name}' is ambiguous: it matches {listed}; "
                                   "write the full dotted name")
    known = [part.FullName() for part in _all_parts(model)]
    candidates = known + [full.rsplit(".", 1)[-1] for full in known]
    raise _core.InputError(f"no model part named '{name}'{nearest(name, candidates, cutoff=0.5)}")
