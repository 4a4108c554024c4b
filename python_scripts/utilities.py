"""Small shared helpers of the Python layer: messages and name suggestions."""
from __future__ import annotations

import difflib
import os
import sys
import tempfile


def warn(message: str) -> None:
    print(f"warning: {message}", file=sys.stderr)


def warn_about_keys_without_effect(settings, defaults, reasons: dict) -> None:
    """``NoEffectWarnings.IfGiven`` for each ``(sub-block or "", key) -> why`` of ``reasons``: the
    keys a reader accepts without acting on them warn when given a value other than the default."""
    from . import _core  # not at the top: test_contact_strategies loads this package without the extension

    for (block, key), why in reasons.items():
        _core.NoEffectWarnings.IfGiven(settings[block] if block else settings, defaults[block] if block else defaults,
                                       key, why)


def nearest(name: str, candidates, cutoff: float = 0.6) -> str:
    """' (did you mean ...?)' for the closest candidates, or ''."""
    close = list(dict.fromkeys(difflib.get_close_matches(name, list(candidates), n=3, cutoff=cutoff)))
    return f" (did you mean {', '.join(repr(c) for c in close)}?)" if close else ""


def write_text_atomically(path: str, text: str) -> None:
    """Writes ``text`` to a temporary file next to ``path`` and renames it over ``path``, so that a
    failed run never leaves a half-written file."""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=".", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(handle, "w") as stream:
            stream.write(text)
        publish_file(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise


def secondary_process() -> bool:
    """Whether this is a process other than rank 0 of a run under ``mpirun``: every rank holds the
    whole model and takes part in the distributed solves, but only rank 0 prints and writes files."""
    from . import _core

    return _core.LaunchedRank() > 0


def partitioned_model() -> bool:
    """Whether each rank of a run under ``mpirun`` cuts the model to its piece after the processes'
    ExecuteInitialize (``MORTARCONTACT_PARTITIONED_MODEL=1``; issue 17, step 3, not yet the default)."""
    from . import _core

    return os.environ.get("MORTARCONTACT_PARTITIONED_MODEL") == "1" and _core.LaunchedProcesses() > 1


def publish_file(temporary: str, path: str, *, every_rank: bool = False) -> None:
    """Renames a finished temporary file over ``path`` with the mode of a file created normally
    (0666 less the umask, usually 0644) instead of mkstemp's private 0600. In a secondary process
    of an mpirun run the file is dropped (rank 0 writes the same one), unless ``every_rank``: a
    rank's own piece of the output of a model cut across the ranks."""
    if secondary_process() and not every_rank:
        os.remove(temporary)
        return
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(temporary, 0o666 & ~umask)
    os.replace(temporary, path)
