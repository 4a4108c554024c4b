"""The bindings `mortarcontact._core` (issue 11, "What to build" items 3 and 5): one submodule per
binding area, named like its `custom_python/add_<area>_to_python.cpp`; every bound class,
function, method, property and enum value documented; every argument named; every name of a
submodule also reachable as `_core.<Name>`. Walks what is bound, so a new binding without a
docstring or with an unnamed argument fails here."""
from __future__ import annotations

import pathlib
import re
import types

import pytest

import mortarcontact
from mortarcontact import _core

CUSTOM_PYTHON = pathlib.Path(__file__).resolve().parents[2] / "custom_python"
UNNAMED_ARGUMENT = re.compile(r"\barg\d+\b")


def _submodules() -> dict[str, types.ModuleType]:
    return {name: value for name, value in vars(_core).items() if isinstance(value, types.ModuleType)}


def _public(namespace) -> dict[str, object]:
    return {name: value for name, value in vars(namespace).items() if not name.startswith("_")}


def _overloads(function) -> list[tuple[str, str]]:
    """(signature, documentation) of each overload of a pybind11 function: its docstring is the
    signature line, then the documentation; overloads are numbered after "Overloaded function."."""
    doc = function.__doc__ or ""
    parts = [doc]
    if "\nOverloaded function.\n" in doc:
        parts = re.split(r"^\d+\. ", doc.split("\nOverloaded function.\n", 1)[1], flags=re.M)[1:]
    return [(part.partition("\n")[0], part.partition("\n")[2].strip()) for part in parts]


def _is_enum(cls: type) -> bool:
    return "__entries" in vars(cls)


def _callables(cls: type):
    """(name, function) of the methods a class binds itself; static methods included."""
    for name, raw in vars(cls).items():
        if name == "_pybind11_conduit_v1_" or isinstance(raw, property):
            continue
        function = getattr(raw, "__func__", raw)  # unwraps instancemethod and staticmethod
        if type(function).__name__ == "builtin_function_or_method":
            yield name, function


def _bound_items():
    """(qualified name, object) of every class, function, method and property of the submodules."""
    for area, module in sorted(_submodules().items()):
        for name, value in sorted(_public(module).items()):
            yield f"{area}.{name}", value
            if isinstance(value, type) and not _is_enum(value):
                for member, function in _callables(value):
                    yield f"{area}.{name}.{member}", function
                for member, raw in vars(value).items():
                    if isinstance(raw, property) and not member.startswith("_"):
                        yield f"{area}.{name}.{member}", raw


def _undocumented(name: str, value) -> list[str]:
    if isinstance(value, property):
        return [name] if not (value.__doc__ or "").strip() else []
    if isinstance(value, type):
        if _is_enum(value):
            doc = (value.__doc__ or "").split("Members:")[0]
            missing = [f"{name}.{entry}" for entry, (_, entry_doc) in value.__entries.items() if not entry_doc]
            return missing + ([name] if not doc.strip() else [])
        return [name] if not (value.__doc__ or "").strip() else []
    if name.rpartition(".")[2].startswith("__") and name.rpartition(".")[2] != "__init__":
        return []  # __repr__, __len__, ...: what they do is the protocol's
    return [f"{name} ({signature})" for signature, doc in _overloads(value) if not doc]


def test_one_submodule_per_binding_file():
    files = {re.fullmatch(r"add_(\w+)_to_python\.cpp", path.name).group(1)
             for path in CUSTOM_PYTHON.glob("add_*_to_python.cpp")}
    assert files, f"no add_<area>_to_python.cpp in {CUSTOM_PYTHON}"
    assert set(_submodules()) == files, "submodules of _core and custom_python/add_<area>_to_python.cpp differ"
    for area, module in _submodules().items():
        assert module.__name__ == f"mortarcontact._core.{area}"
        assert (module.__doc__ or "").strip(), f"_core.{area} has no docstring"
        assert _public(module), f"_core.{area} binds nothing"


def test_submodule_names_are_reexported_at_top_level():
    for area, module in _submodules().items():
        for name, value in _public(module).items():
            assert getattr(_core, name, None) is value, f"_core.{name} is not _core.{area}.{name}"
            if isinstance(value, type):
                assert value.__module__ == module.__name__, f"{name}.__module__ is {value.__module__}"


def test_submodules_do_not_shadow_the_python_package():
    for area in _submodules():
        assert area not in getattr(_core, "__all__", [area]), f"'from _core import *' exports the module {area}"
        assert getattr(mortarcontact, area, None) is not _submodules()[area]


def test_everything_bound_is_documented():
    missing = [item for name, value in _bound_items() for item in _undocumented(name, value)]
    top_level = [value for name, value in _public(_core).items()
                 if callable(value) and not any(value is v for m in _submodules().values() for v in vars(m).values())]
    missing += [f"_core.{value.__name__}" for value in top_level
                if not (_overloads(value)[0][1] if type(value).__name__ == "builtin_function_or_method"
                        else (value.__doc__ or "").strip())]
    assert not missing, f"{len(missing)} bound names without docstring:\n  " + "\n  ".join(missing)


def test_every_argument_is_named():
    unnamed = [f"{name}: {signature}" for name, value in _bound_items()
               if callable(value) and not isinstance(value, type)
               for signature, _ in _overloads(value) if UNNAMED_ARGUMENT.search(signature)]
    assert not unnamed, f"{len(unnamed)} signatures with unnamed arguments:\n  " + "\n  ".join(unnamed)


@pytest.mark.parametrize("function", [mortarcontact.run])
def test_python_entry_points_have_explicit_signatures(function):
    import inspect

    parameters = inspect.signature(function).parameters.values()
    assert all(p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL) for p in parameters)
    assert (function.__doc__ or "").strip()
