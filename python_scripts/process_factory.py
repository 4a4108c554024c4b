"""The process factory: builds the processes named in ``processes`` / ``output_processes`` of a
ProjectParameters.json (spec 1.4).

``create_process(item, model)`` builds one process from an item
``{"python_module", "kratos_module", "process_name", "help", "check", "Parameters"}`` or the
registry form ``{"name", "parameters"}``. Dispatch is by (``kratos_module`` without the
``KratosMultiphysics.`` prefix, ``python_module``) in ``PROCESS_REGISTRY``; ``process_name``,
``help`` and ``check`` are informational only. The registry is filled from the packages below
this module: ``processes`` (kernel and structural processes), ``contact_processes``, ``output`` and ``restart``.
"""
from __future__ import annotations

import re
from contextlib import contextmanager

from . import _core
from .contact_processes import CONTACT_MODULE, CONTACT_PROCESSES
from .output import OUTPUT_PROCESSES
from .process import Process
from .processes import KERNEL_PROCESSES, STRUCTURAL_PROCESSES
from .restart import RESTART_PROCESSES
from .utilities import nearest

KERNEL = "KratosMultiphysics"
STRUCTURAL = "StructuralMechanicsApplication"

#: (normalised kratos_module, python_module) -> process class
PROCESS_REGISTRY: dict[tuple[str, str], type[Process]] = {
    **{(KERNEL, name): cls for name, cls in KERNEL_PROCESSES.items()},
    **{(KERNEL, name): cls for name, cls in OUTPUT_PROCESSES.items()},
    **{(KERNEL, name): cls for name, cls in RESTART_PROCESSES.items()},
    **{(CONTACT_MODULE, name): cls for name, cls in CONTACT_PROCESSES.items()},
    **{(STRUCTURAL, name): cls for name, cls in STRUCTURAL_PROCESSES.items()},
}

_ITEM_KEYS = ["python_module", "kratos_module", "process_name", "help", "check", "Parameters"]
_REGISTRY_FORM_KEYS = ["name", "parameters"]
_NAMESPACE_WORDS = {"processes", "operations", "output_processes"}


def normalise_kratos_module(kratos_module: str) -> str:
    """``KratosMultiphysics.ContactStructuralMechanicsApplication`` -> the application name;
    ``KratosMultiphysics`` stays as it is; a short application name is already normal."""
    prefix = KERNEL + "."
    return kratos_module[len(prefix):] if kratos_module.startswith(prefix) else kratos_module


def _snake_case(name: str) -> str:
    return re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", name).lower() if any(c.isupper() for c in name) else name


def _split_registry_name(name: str) -> tuple[str | None, str]:
    """``"Processes.KratosMultiphysics.AssignVectorVariableProcess"`` or
    ``"KratosMultiphysics.assign_vector_variable_process"`` -> (module, python_module)."""
    parts = [p for p in name.split(".") if p]
    if not parts:
        raise _core.InputError("process item: empty 'name'")
    module_parts = [p for p in parts[:-1] if p.lower() not in _NAMESPACE_WORDS]
    return (".".join(module_parts) or None), _snake_case(parts[-1])


def find_process_class(kratos_module: str | None, python_module: str) -> type[Process]:
    """The registered class, also accepting a python_module registered under exactly one other
    module (user modules name no kratos_module)."""
    module = normalise_kratos_module(kratos_module) if kratos_module else None
    if module is not None and (module, python_module) in PROCESS_REGISTRY:
        return PROCESS_REGISTRY[(module, python_module)]
    same_name = [cls for (m, name), cls in PROCESS_REGISTRY.items() if name == python_module]
    if len(set(same_name)) == 1:
        return same_name[0]
    known = sorted({name for _, name in PROCESS_REGISTRY})
    where = f" of module '{kratos_module}'" if kratos_module else ""
    raise _core.InputError(f"unknown process python_module '{python_module}'{where}"
                           f"{nearest(python_module, known, cutoff=0.4)} "
                           f"(known: {', '.join(known)})")


def create_process(item: _core.Parameters, model: _core.Model) -> Process:
    """Builds the process described by one item of a process list."""
    cls, settings = _class_and_settings(item)
    where = settings.Where()
    with naming_the_item(where):
        process = cls(model, settings)
    process.item_where = where
    return process


def _class_and_settings(item: _core.Parameters) -> tuple[type[Process], _core.Parameters]:
    keys = item.Keys()
    if any(k in keys for k in _REGISTRY_FORM_KEYS):
        item.CheckKeys(_REGISTRY_FORM_KEYS)
        if not item.Has("name"):
            raise _core.InputError(f"{item.Where()}: a process item of the registry form needs 'name'")
        module, python_module = _split_registry_name(item["name"].GetString())
        settings = item["parameters"] if item.Has("parameters") else _core.Parameters()
    else:
        item.CheckKeys(_ITEM_KEYS)
        if not item.Has("python_module"):
            raise _core.InputError(f"{item.Where()}: a process item needs 'python_module' (or 'name')")
        python_module = item["python_module"].GetString()
        module = item["kratos_module"].GetString() if item.Has("kratos_module") else None
        settings = item["Parameters"] if item.Has("Parameters") else _core.Parameters()
    return find_process_class(module, python_module), settings


@contextmanager
def naming_the_item(where: str):
    """Prefixes an InputError whose message does not name the parameters file with the file and
    key path of the process item (``where``), e.g. a model part or variable name that does not
    exist, found only when the process resolves it."""
    try:
        yield
    except _core.InputError as error:
        message = str(error)
        file = where.split(": ", 1)[0] if ": " in where else ""
        if not file or file in message:
            raise
        raise _core.InputError(f"{where}: {message}") from None


def _items(block: _core.Parameters):
    """The items of a ``processes`` (or ``output_processes``) object: lists in lexicographic order
    of their names, file order inside a list (spec 1.4); list names starting with ``_`` are
    commented out and skipped."""
    for list_name in sorted(block.Keys()):
        if list_name.startswith("_"):
            continue
        items = block[list_name]
        if not items.IsArray():
            raise _core.InputError(f"{items.Where()}: a process list must be an array")
        yield from (items[i] for i in range(items.size()))


def create_process_lists(block: _core.Parameters, model: _core.Model) -> list[Process]:
    """All processes of a ``processes`` (or ``output_processes``) object, in the order of ``_items``."""
    return [create_process(item, model) for item in _items(block)]


def parts_kept_whole(block: _core.Parameters) -> list[str] | None:
    """Before the mesh is read: the model parts the processes of ``block`` need whole on every rank
    (``Process.parts_kept_whole``), or None when one of them needs the whole model."""
    names = []
    for item in _items(block):
        cls, settings = _class_and_settings(item)
        kept = cls.parts_kept_whole(settings)
        if kept is None:
            return None
        names += kept
    return names


__all__ = ["PROCESS_REGISTRY", "create_process", "create_process_lists", "find_process_class",
           "naming_the_item", "normalise_kratos_module", "parts_kept_whole"]
