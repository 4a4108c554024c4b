"""Small shared helpers of the Python layer: messages and name suggestions."""
from __future__ import annotations

import difflib
import sys



def warn(message: str) -> None:
    print(f"warning: {message}", file=sys.stderr)


def nearest(name: str, candidates, cutoff: float = 0.6) -> str:
    """' (did you mean ...?)' for the closest candidates, or ''."""
    close = list(dict.fromkeys(difflib.get_close_matches(name, list(candidates), n=3, cutoff=cutoff)))
    return f" (did you mean {', '.join(repr(c) for c in close)}?)" if close else ""
