"""mortarcontact: mortar contact mechanics with a fast C++ core.

``import mortarcontact as mc`` gives the kernel (``mc.Model``, ``mc.Parameters``, variables such
as ``mc.DISPLACEMENT``), the structural substrate and the analysis stage that runs Kratos-format
cases (``mc.run("ProjectParameters.json")``, or ``mc.Analysis(model, parameters)`` over a model
built in Python, e.g. from a meshio mesh with ``mc.import_meshio``).
"""
from __future__ import annotations

import atexit
import os as _os

# libgomp (our OpenMP loops, and OpenBLAS inside UMFPACK / CHOLMOD) spins at a barrier for about
# 300,000 rounds before it sleeps. When the cores also run other work, the spinning thread burns
# the time slices its descheduled partner needs. Measured (benchmarks/hertz/results_wait_policy.md,
# 2 cores, one busy loop per core beside the run): hertz3d_15k takes 121 s spinning, 14.7 s with
# passive waiting and 11.5 s spinning 1000 rounds first; on the idle machine 4.33 s, 5.49 s and
# 4.40 s. So GOMP_SPINCOUNT=1000, unless the user chose OMP_WAIT_POLICY or GOMP_SPINCOUNT. libgomp
# reads it once, when it loads with _core; it is set only for that moment, so that child
# processes (Kratos in the benchmarks) keep their own default.
_short_spin = "OMP_WAIT_POLICY" not in _os.environ and "GOMP_SPINCOUNT" not in _os.environ
if _short_spin:
    _os.environ["GOMP_SPINCOUNT"] = "1000"
from . import _core  # noqa: E402
from ._core import *  # noqa: E402, F403  (kernel classes, variables and flags)
from ._core import Error, InputError, NotImplementedFeatureError, SolutionError  # noqa: E402, F401

if _short_spin:
    del _os.environ["GOMP_SPINCOUNT"]

__version__ = "0.1.0"

_core.RegisterStructuralMechanics()
_core.RegisterThermal()
_core.RegisterContactConditions()
_core.ExportRegisteredNames()
globals().update({name: getattr(_core, name) for name in _core.VariableNames() + _core.FlagNames()})

# The C++ log sink may hold a Python callable; drop it before the interpreter goes away.
atexit.register(_core.ResetLogSink)


def __getattr__(name: str):
    # The Python layer on demand: ``import mortarcontact`` stays as light as the kernel.
    if name in ("Analysis", "ConvergenceFailure"):
        from . import analysis_stage

        return getattr(analysis_stage, name)
    if name == "import_meshio":
        from .solvers.meshio_import import import_meshio

        return import_meshio
    raise AttributeError(f"module 'mortarcontact' has no attribute {name!r}")


def get_cmake_dir() -> str:
    """Folder of the installed CMake package, for out-of-tree C++ plugins:
    ``cmake -Dmortarcontact_DIR=$(python -c 'import mortarcontact; print(mortarcontact.get_cmake_dir())')``."""
    return _os.path.join(_os.path.dirname(__file__), "lib", "cmake", "mortarcontact")


def get_include_dir() -> str:
    """Folder of the installed C++ headers."""
    return _os.path.join(_os.path.dirname(__file__), "include")


def run(project_parameters: str, *, progress: bool = True, stop_on_non_convergence: bool = True):
    """Runs a Kratos-format case from its ProjectParameters.json; returns the finished
    ``StructuralMechanicsAnalysis`` (its ``model``, ``solver`` and ``step_log``).

    project_parameters: path of the ProjectParameters.json; input files not found relative to the
      working directory are looked up next to it.
    progress: show a progress bar (rich) and route the C++ log through it.
    stop_on_non_convergence: raise ``ConvergenceFailure`` when a step does not converge (the last
      converged step is written); False warns and goes on with the next step.
    """
    from .analysis_stage import run_case

    return run_case(project_parameters, progress=progress, stop_on_non_convergence=stop_on_non_convergence)


def load_plugin(path: str) -> None:
    """Loads an out-of-tree C++ plugin (a shared library built against the installed headers and
    CMake package) and calls its ``extern "C" void mortarcontact_register_plugin()``, which
    registers its elements, conditions, laws and variables by name. See
    ``examples/spring_condition_plugin``."""
    import ctypes

    if not _os.path.isfile(path):
        raise InputError(f"plugin {path} not found")
    library = ctypes.CDLL(_os.path.abspath(path), mode=ctypes.RTLD_GLOBAL)
    try:
        register = library.mortarcontact_register_plugin
    except AttributeError:
        raise InputError(f"plugin {path} has no function mortarcontact_register_plugin()") from None
    register()
    _core.ExportRegisteredNames()
    globals().update({name: getattr(_core, name) for name in _core.VariableNames() + _core.FlagNames()})
    _loaded_plugins.append(library)


_loaded_plugins = []
