"""Small shared helpers of the Python layer: messages and model-part name resolution."""
from __future__ import annotations

import difflib
import sys

from . import _core


def warn(message: str) -> None:
    print(f"warning: {message}", file=sys.stderr)


def nearest(name: str, candidates) -> str:
    """' (did you mean ...?)' for the closest candidates, or ''."""
    close = difflib.get_close_matches(name, list(candidates), n=3, cutoff=0.6)
    return f" (did you mean {', '.join(repr(c) for c in close)}?)" if close else ""


def _all_parts(part):
    for sub in part.SubModelParts:
        yield sub
        yield from _all_parts(sub)


def resolve_model_part(model: _core.Model, name: str):
    """Model part of a settings name (spec 1.6): a dotted full path, the root, the legacy alias
    'computing_domain' (the root), or a bare legacy sub-part name searched in every root."""
    if model.HasModelPart(name):
        return model.GetModelPart(name)
    head, _, tail = name.partition(".")
    if tail == "computing_domain" and model.HasModelPart(head):
        return model.GetModelPart(head)
    if "." not in name:
        matches = [p for root in model.ModelPartNames() for p in _all_parts(model.GetModelPart(root))
                   if p.Name == name]
        if len(matches) == 1:
            return matches[0]
        if len(matches) > 1:
            raise _core.InputError(f"model part name '{name}' is ambiguous: "
                                   + ", ".join(p.FullName() for p in matches))
    known = [p.FullName() for root in model.ModelPartNames()
             for p in [model.GetModelPart(root), *_all_parts(model.GetModelPart(root))]]
    raise _core.InputError(f"no model part named '{name}'{nearest(name, known)}")
