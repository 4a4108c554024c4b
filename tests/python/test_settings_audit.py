"""Issue 18, item 1: every settings key that our readers accept acts (a test shows its effect),
warns that it has no effect here, stops the run with an error naming it, or is out of scope for a
stated reason. ``settings_audit.tsv`` lists the keys (from the settings specification and from the
readers' own defaults) with their status; this file walks it:

- "acts" keys: the referenced test exists and names the key, or (evidence "results" / "log") the
  contact case of test_bad_input.py run with the given value differs from the default run;
- "warns" keys: the run with the given value warns "key '<key>' = <value> at <file>: <path> has no
  effect in mortarcontact: ..." once, and the default run warns about nothing;
- "rejects" keys: the run with the given value fails with an error naming the key;
- no key accepted by a reader (solver settings, contact_settings and its C++ owners, the processes,
  the search and the ALM estimate) is missing from the list.
The rest of this file holds the effect tests the list refers to."""
from __future__ import annotations

import ast
import csv
import hashlib
import json
import os
import pathlib
import re

import pytest
from test_bad_input import contact_case, square_case

import mortarcontact as mc
from mortarcontact import _core
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.contact_processes import CONTACT_PROCESSES
from mortarcontact.process_factory import PROCESS_REGISTRY
from mortarcontact.processes.from_json_check_result_process import CheckResultError
from mortarcontact.project_parameters import PROBLEM_DATA_DEFAULTS, TOP_LEVEL_KEYS, read_project_parameters
from mortarcontact.solvers.contact_mechanical_solver import contact_settings_defaults
from mortarcontact.solvers.mpc_contact_mechanical_solver import mpc_contact_settings_defaults
from mortarcontact.solvers.solver_settings import STRUCTURAL_DEFAULTS

HERE = pathlib.Path(__file__).resolve().parent
STATUSES = ("acts", "warns", "rejects", "block", "out_of_scope")
#: where each block of the list lives in the contact case's parameters
BLOCKS = {
    "<root>": [],
    "problem_data": ["problem_data"],
    "solver_settings": ["solver_settings"],
    "contact_process": ["processes", "contact_process_list", 0, "Parameters"],
    "assign_process": ["processes", "constraints_process_list", 0, "Parameters"],
    "json_output_process": ["processes", "json_output_process", 0, "Parameters"],
    "vtk_output_process": ["output_processes", "vtk_output", 0, "Parameters"],
}
#: readers whose keys are one block of the list
ASSIGNMENTS = {"assign_scalar_variable_process", "assign_vector_variable_process", "assign_vector_by_direction_process",
               "assign_scalar_variable_to_conditions_process", "assign_vector_variable_to_conditions_process",
               "assign_vector_by_direction_to_condition_process"}
NO_EFFECT = re.compile(r"key '(?P<key>\w+)' = (?P<value>.*?) at (?P<where>.*?) has no effect in mortarcontact: \S")


def _rows():
    with open(HERE / "settings_audit.tsv") as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    rows = []
    for fields in csv.reader(lines, delimiter="\t", quoting=csv.QUOTE_NONE):
        fields += [""] * (5 - len(fields))
        block, key, status, value, evidence = fields[:5]
        rows.append({"block": block, "key": key, "status": status, "value": value, "evidence": evidence})
    return rows


ROWS = _rows()


def _ids(row) -> str:
    return f"{row['block']}.{row['key']}"


def _of(status, evidence=None):
    return [r for r in ROWS if r["status"] == status and (evidence is None or r["evidence"] in evidence)]


# == the list itself ===================================================================================
def test_every_row_is_well_formed():
    seen = set()
    for row in ROWS:
        where = f"{row['block']}.{row['key']}"
        assert row["status"] in STATUSES, f"{where}: unknown status {row['status']!r}"
        assert where not in seen, f"{where} is listed twice"
        seen.add(where)
        if row["value"]:
            json.loads(row["value"])
        if row["status"] in ("warns", "rejects") and row["key"] != "*":
            assert row["value"], f"{where}: a {row['status']} key needs the value that shows it"
        if row["status"] in ("acts", "rejects", "out_of_scope"):
            assert row["evidence"], f"{where}: {row['status']} needs its evidence"


def _test_functions():
    """{file::test: its source, decorators included, and the module-level assignments of its file
    (the tables a parametrized test runs over)}."""
    functions = {}
    for path in HERE.glob("test_*.py"):
        tree = ast.parse(path.read_text())
        source = path.read_text()
        tables = "\n".join(ast.get_source_segment(source, node) for node in tree.body if isinstance(node, ast.Assign))
        for node in tree.body:
            if isinstance(node, ast.FunctionDef) and node.name.startswith("test_"):
                first = min([node.lineno, *(d.lineno for d in node.decorator_list)])
                functions[f"{path.name}::{node.name}"] = "\n".join(
                    [*source.splitlines()[first - 1:node.end_lineno], tables])
    return functions


def _cpp_test(evidence: str) -> str | None:
    """The body of a GoogleTest named "<file under tests/cpp>::<test name>", or None."""
    path, _, name = evidence.partition("::")
    source = HERE.parent / "cpp" / path
    if not source.is_file():
        return None
    found = re.search(rf"^TEST\(\w+, {re.escape(name)}\).*?(?=^TEST\(|\Z)", source.read_text(), re.S | re.M)
    return found.group(0) if found else None


@pytest.mark.parametrize("row", [r for r in _of("acts") + _of("rejects") if "::" in r["evidence"]], ids=_ids)
def test_acting_key_names_a_test_that_exists_and_uses_it(row):
    body = _cpp_test(row["evidence"]) if ".cpp::" in row["evidence"] else _test_functions().get(row["evidence"])
    assert body is not None, f"{row['block']}.{row['key']}: no test {row['evidence']}"
    key = row["key"] if row["key"] != "*" else row["block"]
    assert key in body, f"{row['evidence']} does not mention {key}"


def _listed(block: str) -> set[str]:
    return {r["key"] for r in ROWS if r["block"] == block}


def _walk(block: str, defaults: dict, found: dict) -> None:
    for key, value in defaults.items():
        found.setdefault(block, set()).add(key)
        slots = isinstance(value, dict) and set(value) == {str(k) for k in range(10)}
        if isinstance(value, dict) and value and not slots:
            _walk(f"{block}.{key}", value, found)


def _accepted_keys() -> dict[str, set[str]]:
    """{block of the list: keys accepted by the readers of that block}."""
    found = {"<root>": set(TOP_LEVEL_KEYS)}
    _walk("problem_data", json.loads(PROBLEM_DATA_DEFAULTS), found)
    _walk("solver_settings", json.loads(STRUCTURAL_DEFAULTS), found)
    _walk("solver_settings.contact_settings", json.loads(contact_settings_defaults().WriteJsonString()), found)
    _walk("solver_settings.mpc_contact_settings", json.loads(mpc_contact_settings_defaults().WriteJsonString()), found)
    for (_, name), cls in PROCESS_REGISTRY.items():
        if name in ("alm_contact_process", "penalty_contact_process"):
            block = "contact_process"
        elif name in ASSIGNMENTS:
            block = "assign_process"
        else:
            block = name
        _walk(block, json.loads(cls.GetDefaultParameters().WriteJsonString()), found)
    search = json.loads(_core.ContactSearchProcess.GetDefaultParameters().WriteJsonString())
    _walk("contact_process.search_parameters", search, found)
    alm = json.loads(_core.ALMVariablesCalculationProcess.GetDefaultParameters().WriteJsonString())
    _walk("contact_process.advance_ALM_parameters", alm, found)
    return found


def test_no_accepted_key_is_missing_from_the_list():
    missing = []
    for block, keys in _accepted_keys().items():
        listed = _listed(block)
        if any("*" in _listed(".".join(block.split(".")[:n])) for n in range(1, block.count(".") + 2)):
            continue
        missing += [f"{block}.{key}" for key in sorted(keys - listed)]
    assert not missing, f"accepted but not audited (add them to settings_audit.tsv): {missing}"


def test_every_contact_process_is_audited():
    for name in CONTACT_PROCESSES:
        block = "contact_process" if name in ("alm_contact_process", "penalty_contact_process") else name
        assert _listed(block), f"{name}: no row in settings_audit.tsv"


# == running the contact case with one key changed ==========================================================
def _set(params: dict, block: str, key: str, value) -> None:
    head, _, rest = block.partition(".")
    target = params
    for step in BLOCKS[head] + (rest.split(".") if rest else []):
        if isinstance(target, dict) and step not in target:
            target[step] = {}
        target = target[step]
    target[key] = value


def _run(folder: pathlib.Path, base=contact_case, edit=None):
    """(analysis or the error, captured log) of the case written in ``folder``, edited by ``edit``."""
    folder.mkdir(parents=True, exist_ok=True)
    path = base(str(folder))
    with open(path) as f:
        params = json.load(f)
    # The json output of the base cases samples once a second, after the end of their one step.
    for item in params["processes"].get("json_output_process", []):
        item["Parameters"]["time_frequency"] = 0.0
    if edit:
        edit(params)
    with open(path, "w") as f:
        json.dump(params, f, indent=2)
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        analysis = StructuralMechanicsAnalysis(mc.Model(), read_project_parameters(path), progress=False,
                                               case_dir=str(folder))
        analysis.Run()
        return analysis
    except (mc.Error, CheckResultError) as error:
        return error
    finally:
        os.chdir(cwd)


def _nodal_values(analysis) -> list:
    """(id, displacement and, if solved for, the contact multiplier) of every node, 10 digits."""
    assert not isinstance(analysis, Exception), analysis
    root = analysis.model.GetModelPart("Structure")
    nodes = []
    for node in root.Nodes:
        values = list(node.GetSolutionStepValue(mc.DISPLACEMENT))
        if root.HasNodalSolutionStepVariable(mc.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE):
            values.append(node.GetSolutionStepValue(mc.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE))
        nodes.append((node.Id, [float(f"{v:.10g}") for v in values]))
    return nodes


def _fingerprint(analysis, folder: pathlib.Path):
    """What a run produced: nodal solution and coordinates, steps and iterations, strategy, contact
    pairs and ProcessInfo values, and the files written in ``folder`` with their contents."""
    root = analysis.model.GetModelPart("Structure")
    nodes = _nodal_values(analysis)
    coordinates = [float(f"{x:.10g}") for x in root.NodeCoordinates(False).ravel()]
    variables = [name for name in ("VELOCITY", "ACCELERATION", "ROTATION")
                 if root.HasNodalSolutionStepVariable(getattr(mc, name))]
    info = root.ProcessInfo
    info_values = {name: info.GetValue(getattr(mc, name)) for name in (
        "INITIAL_PENALTY", "SCALE_FACTOR", "ZERO_TOLERANCE_FACTOR", "ACTIVE_CHECK_FACTOR", "CONSIDER_NORMAL_VARIATION",
        "STEP", "TIME") if info.Has(getattr(mc, name))}
    pairs = []
    if root.HasSubModelPart("ComputingContact"):
        pairs = sorted((c.Info(), c.GetProperties().Id) for c in root.GetSubModelPart("ComputingContact").Conditions)
    files = {}
    for path in sorted(folder.rglob("*")):
        if path.is_file() and not path.name.startswith("contact"):
            files[str(path.relative_to(folder))] = hashlib.sha1(path.read_bytes()).hexdigest()
    steps = [(step, time, iterations, converged) for step, time, iterations, converged, _ in analysis.step_log]
    return {"nodes": nodes, "coordinates": coordinates, "variables": variables, "steps": steps,
            "strategy": type(analysis.solver.strategy).__name__, "info": info_values, "pairs": pairs, "files": files}


def _normalised_log(text: str) -> str:
    return re.sub(r"\d+(\.\d+)?(e[-+]?\d+)?", "#", text)


def _run_logged(folder, base=contact_case, edit=None):
    """(analysis or the error, the C++ log of the run: warnings and echo output)."""
    messages = []
    _core.SetLogSink(lambda level, message: messages.append(message))
    try:
        result = _run(folder, base, edit)
    finally:
        _core.ResetLogSink()
    return result, "\n".join(messages)


def _path_of(block: str) -> list:
    head, _, rest = block.partition(".")
    return BLOCKS[head] + (rest.split(".") if rest else [])


@pytest.fixture(scope="module")
def default_runs(tmp_path_factory):
    """(fingerprint, log) of the contact case as it is, quiet or at echo level 1; run once."""
    cache = {}

    def get(verbose: bool):
        if verbose not in cache:
            folder = tmp_path_factory.mktemp("default")
            result, log = _run_logged(folder, edit=_verbose if verbose else None)
            cache[verbose] = (_fingerprint(result, folder), log)
        return cache[verbose]
    return get


@pytest.fixture(scope="module")
def warnings_of_all_keys(tmp_path_factory):
    """The log of one run of the contact case with every "warns" key set to its value (but those
    translated to another key, which run apart)."""
    rows = [r for r in _of("warns") if r["key"] != "*" and not r["evidence"]]

    def set_all(params):
        for row in rows:
            _set(params, row["block"], row["key"], json.loads(row["value"]))
    return _run_logged(tmp_path_factory.mktemp("warned"), edit=set_all)[1]


def test_the_default_run_warns_about_nothing(tmp_path):
    analysis, log = _run_logged(tmp_path / "default")
    assert not isinstance(analysis, Exception), analysis
    assert "has no effect" not in log, log


def _verbose(params):
    params["problem_data"]["echo_level"] = params["solver_settings"]["echo_level"] = 1


@pytest.mark.parametrize("row", _of("acts", ("results", "log")), ids=_ids)
def test_acting_key_changes_the_run(row, tmp_path, default_runs):
    """A log is compared at echo level 1 (but for the echo levels themselves)."""
    verbose = row["evidence"] == "log" and row["key"] != "echo_level"
    base, base_log = default_runs(verbose)

    def change(params):
        if verbose:
            _verbose(params)
        _set(params, row["block"], row["key"], json.loads(row["value"]))
    changed, log = _run_logged(tmp_path, edit=change)
    assert not isinstance(changed, Exception), changed
    assert "has no effect" not in log, log
    if row["evidence"] == "log":
        assert _normalised_log(log) != _normalised_log(base_log)
    else:
        assert _fingerprint(changed, tmp_path) != base


@pytest.mark.parametrize("row", [r for r in _of("warns") if r["key"] != "*"], ids=_ids)
def test_key_without_effect_warns_once(row, tmp_path, warnings_of_all_keys):
    """The warning names the key where the user wrote it: the file and the JSON path."""
    if row["evidence"]:
        log = _run_logged(tmp_path, edit=lambda p: _set(p, row["block"], row["key"], json.loads(row["value"])))[1]
    else:
        log = warnings_of_all_keys
    named = row["evidence"] or row["key"]
    path = _path_of(row["block"])
    suffix = f"{path[-1]}.{named}" if path else f": {named}"
    warnings = [m for m in NO_EFFECT.finditer(log) if m["key"] == named and m["where"].endswith(suffix)]
    assert len(warnings) == 1, f"expected one warning about {suffix}: {log}"
    assert "contact_parameters.json: " in warnings[0]["where"], warnings[0]["where"]


@pytest.mark.parametrize("row", [r for r in _of("rejects") if "::" not in r["evidence"]], ids=_ids)
def test_rejected_key_stops_the_run_naming_it(row, tmp_path):
    if row["block"] in BLOCKS or row["block"].split(".")[0] in BLOCKS:
        block, key = row["block"], row["key"]
        if key == "*":
            block, _, key = block.rpartition(".")
        value = json.loads(row["value"])
        result, _ = _run_logged(tmp_path, edit=lambda p: _set(p, block, key, value))
    else:  # a contact process that is not implemented, with its defaults
        try:
            CONTACT_PROCESSES[row["block"]](mc.Model(), _core.Parameters())
            result = None
        except mc.Error as error:
            result = error
    assert isinstance(result, mc.Error), f"{row['block']}.{row['key']}: the run did not fail"
    assert row["evidence"] in str(result), str(result)


# == effect tests the list refers to =========================================================================
def _solver(**changes):
    return lambda params: params["solver_settings"].update(changes)


def _contact(**changes):
    return lambda params: params["solver_settings"]["contact_settings"].update(changes)


def _process(**changes):
    return lambda params: params["processes"]["contact_process_list"][0]["Parameters"].update(changes)


def _dense_square(folder) -> str:
    """The square of test_bad_input.py with a density, for the dynamic solvers."""
    path = square_case(folder)
    with open(os.path.join(folder, "square_materials.json")) as f:
        materials = json.load(f)
    materials["properties"][0]["Material"]["Variables"]["DENSITY"] = 1000.0
    with open(os.path.join(folder, "square_materials.json"), "w") as f:
        json.dump(materials, f)
    return path


def test_legacy_top_level_process_lists_run(tmp_path):
    """The pre-2018 layout: constraints_process_list, loads_process_list and contact_processes at the
    top level run as if they were inside ``processes`` (spec 1.1)."""
    def legacy(params):
        processes = params.pop("processes")
        params["constraints_process_list"] = processes["constraints_process_list"]
        params["loads_process_list"] = processes["loads_process_list"]
        params["contact_processes"] = processes["contact_process_list"]
    assert _nodal_values(_run(tmp_path / "legacy", edit=legacy)) == _nodal_values(_run(tmp_path / "default"))


def test_legacy_problem_data_keys_move_to_the_solver(tmp_path):
    """model_part_name, domain_size and time_step in problem_data (spec 1.2) reach the solver."""
    def legacy(params):
        solver = params["solver_settings"]
        params["problem_data"].update(model_part_name=solver.pop("model_part_name"),
                                      domain_size=solver.pop("domain_size"),
                                      time_step=solver.pop("time_stepping")["time_step"])
    assert _nodal_values(_run(tmp_path / "legacy", edit=legacy)) == _nodal_values(_run(tmp_path / "default"))


def test_buffer_size_sets_the_history_depth(tmp_path):
    analysis = _run(tmp_path, edit=_solver(buffer_size=4))
    assert analysis.model.GetModelPart("Structure").GetBufferSize() == 4


def test_explicit_time_integration_is_reported(tmp_path):
    """time_integration_method picks the dynamic solver: implicit runs (the square), explicit contact
    with a multiplier formulation is not implemented."""
    error = _run(tmp_path / "explicit", edit=_solver(solver_type="Dynamic", time_integration_method="explicit"))
    assert isinstance(error, mc.NotImplementedFeatureError) and "explicit contact" in str(error), error
    implicit = _run(tmp_path / "implicit", base=_dense_square, edit=_solver(solver_type="Dynamic",
                                                                          time_integration_method="implicit"))
    assert implicit.model.GetModelPart("Structure").HasNodalSolutionStepVariable(mc.ACCELERATION)


@pytest.mark.parametrize("level", [1, 2])
def test_explicit_time_step_prediction(tmp_path, capfd, monkeypatch, level):
    """time_step_prediction_level 1: the explicit step is fraction_delta_time x the critical one
    (ElementStableTimeStep), bounded by max_delta_time, time_stepping unread; 2: predicted again
    every delta_time_refresh steps. Without the prediction its keys warn that they have no effect."""
    from mortarcontact.solvers.mechanical_solver import MechanicalSolver

    predictions = []
    critical_time_step = MechanicalSolver.critical_time_step
    monkeypatch.setattr(MechanicalSolver, "critical_time_step",
                        lambda solver: predictions.append(1) or critical_time_step(solver))
    explicit = {"solver_type": "Dynamic", "time_integration_method": "explicit", "time_stepping": {"time_step": 1.0}}
    refresh = {"delta_time_refresh": 2} if level > 1 else {}
    analysis = _run(tmp_path / "predicted", base=_dense_square, edit=_solver(
        **explicit, time_step_prediction_level=level, fraction_delta_time=0.25, **refresh))
    assert not isinstance(analysis, Exception), analysis
    root = analysis.model.GetModelPart("Structure")
    critical = analysis.solver.strategy.ElementStableTimeStep()
    assert root.ProcessInfo.GetValue(mc.DELTA_TIME) == pytest.approx(0.25 * critical, rel=1e-12)
    steps = root.ProcessInfo.GetValue(mc.STEP)
    assert len(predictions) == (1 if level == 1 else (steps + 1) // 2)
    assert "has no effect" not in capfd.readouterr().err
    capped = _run(tmp_path / "capped", base=_dense_square, edit=_solver(
        **explicit, time_step_prediction_level=level, max_delta_time=0.1 * critical))
    assert capped.model.GetModelPart("Structure").ProcessInfo.GetValue(mc.DELTA_TIME) == pytest.approx(0.1 * critical)
    _run(tmp_path / "unread", base=_dense_square, edit=_solver(
        **{**explicit, "time_stepping": {"time_step": 0.1 * critical}}, max_delta_time=0.5, delta_time_refresh=10))
    err = capfd.readouterr().err
    assert "'max_delta_time' = 0.5" in err and "'delta_time_refresh' = 10" in err


def test_ignore_variables_not_in_solution_step_data(tmp_path):
    """An mdpa block of an unknown variable is an error, or skipped with a warning when asked."""
    def with_unknown_block(folder):
        path = contact_case(folder)
        with open(os.path.join(folder, "contact.mdpa"), "a") as f:
            f.write("\nBegin NodalData NOT_A_VARIABLE\n1 0 1.0\nEnd NodalData\n")
        return path
    assert isinstance(_run(tmp_path / "strict", base=with_unknown_block), mc.InputError)
    tolerant = _run(tmp_path / "tolerant", base=with_unknown_block,
                    edit=lambda p: p["solver_settings"]["model_import_settings"].update(
                        ignore_variables_not_in_solution_step_data=True))
    assert not isinstance(tolerant, Exception), tolerant


@pytest.mark.parametrize("stepping", [{"time_step_table": [[0.0, 0.25], [1.0, 0.25]]},
                                      {"time_step_intervals": {"0": {"interval": [0.0, "End"], "time_step": 0.25}}}])
def test_time_step_table_and_intervals(tmp_path, stepping):
    analysis = _run(tmp_path, edit=_solver(time_stepping=stepping))
    assert [round(entry[1], 12) for entry in analysis.step_log] == [0.25, 0.5, 0.75, 1.0]


def test_rotation_dofs_add_rotations(tmp_path):
    analysis = _run(tmp_path, base=square_case, edit=_solver(rotation_dofs=True))
    assert analysis.model.GetModelPart("Structure").HasNodalSolutionStepVariable(mc.ROTATION)


def _iterations(analysis):
    assert not isinstance(analysis, Exception), analysis
    return [entry[2] for entry in analysis.step_log]


def _total_lagrangian_square(folder) -> str:
    """The square of test_bad_input.py with finite-strain elements: the stiffness changes with the load."""
    path = square_case(folder)
    mdpa = os.path.join(folder, "square.mdpa")
    with open(mdpa) as f:
        text = f.read()
    with open(mdpa, "w") as f:
        f.write(text.replace("SmallDisplacementElement2D4N", "TotalLagrangianElement2D4N"))
    return path


def _increments(analysis) -> list[float]:
    assert not isinstance(analysis, Exception), analysis
    return [record.increment_norm for record in analysis.solver.LastIterationHistory()]


def test_use_old_stiffness_in_first_iteration(tmp_path):
    """The first iteration of step 2 with the stiffness of step 1 takes another increment; the contact
    strategies build the matrix at every iteration, so there the key warns."""
    two_steps = {"time_stepping": {"time_step": 0.5}}
    fresh = _increments(_run(tmp_path / "fresh", base=_total_lagrangian_square, edit=_solver(**two_steps)))
    reused = _increments(_run(tmp_path / "reused", base=_total_lagrangian_square, edit=_solver(
        **two_steps, use_old_stiffness_in_first_iteration=True)))
    assert reused[0] != pytest.approx(fresh[0], rel=1e-3)
    _, log = _run_logged(tmp_path / "contact", edit=_solver(use_old_stiffness_in_first_iteration=True))
    assert [m["key"] for m in NO_EFFECT.finditer(log)] == ["use_old_stiffness_in_first_iteration"], log


def test_line_search_advanced_settings(tmp_path):
    """Step lengths capped at 0.5 of Newton's keep the finite-strain square from converging in
    max_iteration; the default line search converges."""
    def line_search(**advanced):
        return _solver(solving_strategy_settings={"type": "line_search", "advanced_settings": advanced},
                       time_stepping={"time_step": 0.5})
    assert _increments(_run(tmp_path / "default", base=_total_lagrangian_square, edit=line_search()))
    short = _run(tmp_path / "short", base=_total_lagrangian_square, edit=line_search(
        max_alpha=0.5, first_alpha_value=0.1, second_alpha_value=0.2))
    assert isinstance(short, mc.SolutionError) and "did not converge" in str(short), short


def test_clear_storage_warns_only_without_contact(tmp_path):
    """Kratos clears the strategy's storage each step; the results are the same without. Contact
    solvers clear it (forced, as Kratos): no warning there."""
    _, log = _run_logged(tmp_path / "square", base=square_case, edit=_solver(clear_storage=True))
    assert [m["key"] for m in NO_EFFECT.finditer(log)] == ["clear_storage"], log
    _, log = _run_logged(tmp_path / "contact", edit=_solver(clear_storage=True))
    assert "has no effect" not in log, log


def test_displacement_tolerances(tmp_path):
    criterion = {"convergence_criterion": "displacement_criterion"}
    tight = _iterations(_run(tmp_path / "tight", base=square_case, edit=_solver(
        **criterion, displacement_relative_tolerance=1e-12, displacement_absolute_tolerance=1e-14)))
    loose_relative = _iterations(_run(tmp_path / "relative", base=square_case, edit=_solver(
        **criterion, displacement_relative_tolerance=10.0, displacement_absolute_tolerance=1e-14)))
    loose_absolute = _iterations(_run(tmp_path / "absolute", base=square_case, edit=_solver(
        **criterion, displacement_relative_tolerance=1e-12, displacement_absolute_tolerance=10.0)))
    assert loose_relative < tight and loose_absolute < tight


def test_auxiliary_variables_and_dofs(tmp_path):
    analysis = _run(tmp_path, base=square_case, edit=_solver(
        auxiliary_variables_list=["NODAL_AREA"], auxiliary_dofs_list=["TEMPERATURE"],
        auxiliary_reaction_list=["NODAL_H"]))
    root = analysis.model.GetModelPart("Structure")
    assert root.HasNodalSolutionStepVariable(mc.NODAL_AREA) and root.HasNodalSolutionStepVariable(mc.TEMPERATURE)
    assert all(node.HasDofFor(mc.TEMPERATURE) for node in root.Nodes)


@pytest.mark.parametrize("key, value", [("damp_factor_m", -0.1), ("newmark_beta", 0.3), ("rayleigh_alpha", 10.0),
                                        ("rayleigh_beta", 0.1)])
def test_dynamic_scheme_keys(tmp_path, key, value):
    """Each key of the implicit dynamic schemes changes the dynamic response of the square
    (newmark_beta with the Newmark scheme, the others with Bossak)."""
    scheme = {"solver_type": "Dynamic", "scheme_type": "newmark" if key == "newmark_beta" else "bossak",
              "time_stepping": {"time_step": 0.25}}
    default = _run(tmp_path / "default", base=_dense_square, edit=_solver(**scheme))
    changed = _run(tmp_path / "changed", base=_dense_square, edit=_solver(**scheme, **{key: value}))
    assert _nodal_values(changed) != _nodal_values(default)


def test_legacy_builder_keys():
    from mortarcontact.solvers.solver_settings import translate_legacy_solver_settings

    def builder(settings: dict) -> str:
        parameters = _core.Parameters(json.dumps(settings))
        translate_legacy_solver_settings(parameters)
        return parameters["builder_and_solver_settings"]["type"].GetString()
    assert builder({"block_builder": False}) == "elimination"
    assert builder({"block_builder": True}) == "block"
    assert builder({"builder_and_solver_settings": {"use_block_builder": False}}) == "elimination"
    assert builder({"builder_and_solver_settings": {"use_block_builder": True, "use_lagrange_BS": True}}) \
        == "block_lagrange"


def test_convergence_table_keys(tmp_path):
    """The contact solvers print their convergence table (fancy_convergence_criterion) at echo
    level 1; without it the criteria print line by line."""
    _, table = _run_logged(tmp_path / "table", edit=_solver(echo_level=1))
    _, lines = _run_logged(tmp_path / "lines", edit=lambda p: (
        _solver(echo_level=1)(p), _contact(fancy_convergence_criterion=False)(p)))
    assert _normalised_log(table) != _normalised_log(lines)


def test_ensure_contact_fails_without_contact(tmp_path):
    """Bodies far apart: a legitimate open state, unless ensure_contact asks for contact."""
    from test_bad_input import _mutated_contact_case

    def far(folder):
        return _mutated_contact_case(pathlib.Path(folder), 11.0)
    assert not isinstance(_run(tmp_path / "open", base=far), Exception)
    error = _run(tmp_path / "ensured", base=far, edit=_contact(ensure_contact=True))
    assert isinstance(error, mc.Error) and "ensure_contact" in str(error), error


@pytest.mark.parametrize("criterion, keys", [
    ("contact_residual_criterion", ("contact_residual_relative_tolerance", "contact_residual_absolute_tolerance")),
    ("contact_displacement_criterion", ("contact_displacement_relative_tolerance",
                                        "contact_displacement_absolute_tolerance")),
    ("contact_residual_criterion", ("rotation_residual_relative_tolerance", "rotation_residual_absolute_tolerance")),
    ("contact_displacement_criterion", ("rotation_relative_tolerance", "rotation_absolute_tolerance"))])
def test_contact_block_tolerances(criterion, keys):
    """Each tolerance of contact_settings reaches its block of the contact criterion (the
    mechanical criterion's tolerances per DoF family)."""
    family = "rotation" if keys[0].startswith("rotation") else "multiplier"

    def tolerances(value):
        solver = {"convergence_criterion": criterion, "rotation_dofs": True,
                  "contact_settings": {"mortar_type": "ALMContactFrictionless", **dict.fromkeys(keys, value)}}
        settings = _core.Parameters(json.dumps(solver))
        from mortarcontact.solvers.solver_settings import validate_solver_settings
        settings.AddValue("model_part_name", _core.Parameters('"Structure"'))
        settings.AddValue("domain_size", _core.Parameters("2"))
        validate_solver_settings(settings)
        from mortarcontact.contact_strategies import create_contact_convergence_criteria
        criteria = create_contact_convergence_criteria(settings, _core.ContactFormulation.Get("ALMContactFrictionless"))
        return criteria.Mechanical().Tolerances()[family][1:]
    assert tolerances(0.123) == (0.123, 0.123)
    assert tolerances(0.456) == (0.456, 0.456)


def test_silent_strategy(tmp_path):
    _, silent = _run_logged(tmp_path / "silent", edit=_solver(echo_level=2))
    _, verbose = _run_logged(tmp_path / "verbose", edit=lambda p: (
        _solver(echo_level=2)(p), _contact(silent_strategy=False)(p)))
    assert _normalised_log(silent) != _normalised_log(verbose)


def _contact_linear_solver(tmp_path, mortar_type="ALMContactFrictionless", contact_type="Frictionless", **contact):
    analysis = _run(tmp_path, edit=lambda p: (_contact(mortar_type=mortar_type, **contact)(p),
                                              _process(contact_type=contact_type)(p)))
    assert not isinstance(analysis, Exception), analysis
    return analysis.solver._new_linear_solver().Name()


def test_rescale_linear_solver_wraps_the_solver(tmp_path):
    assert _contact_linear_solver(tmp_path / "plain") == "umfpack"
    assert _contact_linear_solver(tmp_path / "scaled", rescale_linear_solver=True) == "scaling(umfpack)"
    settings = _core.Parameters(json.dumps({"solver_type": "klu", "scaling": True}))
    assert _core.CreateLinearSolver(settings).Name() == "scaling(klu)"


def test_mixed_ulm_keys(tmp_path):
    components = {"mortar_type": "ALMContactFrictionlessComponents", "contact_type": "FrictionlessComponents"}
    assert _contact_linear_solver(tmp_path / "condensed", **components).startswith("mixed_ulm_linear_solver")
    assert _contact_linear_solver(tmp_path / "full", **components, use_mixed_ulm_solver=False) == "umfpack"
    other = {"solver_type": "umfpack"}
    assert _contact_linear_solver(tmp_path / "other", **components, mixed_ulm_solver_parameters=other) == "umfpack"


def test_linear_solver_keys():
    """solver_type picks the solver; the iterative ones follow tolerance, max_iteration (or
    max_iteration_number), preconditioner_type and gmres_krylov_space_dimension; sparse_lu its ordering."""
    import numpy as np
    import scipy.sparse as sp

    n = 60
    A = sp.diags([-1.0, 2.05, -1.0], [-1, 0, 1], shape=(n, n), format="csc")
    b = np.ones(n)

    def solve(**settings):
        solver = _core.CreateLinearSolver(_core.Parameters(json.dumps(settings)))
        x = solver.Solve(A, b)
        return solver, float(np.linalg.norm(A @ x - b)), solver.IterationsNumber()
    assert solve(solver_type="klu")[0].Name() == "klu"
    _, tight, _ = solve(solver_type="bicgstab", tolerance=1e-12)
    _, loose, _ = solve(solver_type="bicgstab", tolerance=1e-2)
    assert loose > tight
    for key, limit in (("max_iteration", 3), ("max_iteration_number", 4)):
        with pytest.raises(mc.SolutionError, match=f"max_iteration {limit}"):
            solve(solver_type="cg", tolerance=1e-14, **{key: limit})
    assert solve(solver_type="cg", tolerance=1e-14, max_iteration=200)[2] > 4
    plain = solve(solver_type="gmres", tolerance=1e-12, preconditioner_type="none")[2]
    assert solve(solver_type="gmres", tolerance=1e-12, preconditioner_type="ilu0")[2] != plain
    try:
        restarted = solve(solver_type="gmres", tolerance=1e-12, gmres_krylov_space_dimension=5)[2]
    except mc.SolutionError:  # restarted every 5 iterations, GMRES stalls on this system
        restarted = None
    assert restarted != plain
    with pytest.raises(mc.InputError, match="ordering"):
        solve(solver_type="sparse_lu_eigen", ordering="nested")


def _pairs(analysis):
    assert not isinstance(analysis, Exception), analysis
    part = analysis.model.GetModelPart("Structure").GetSubModelPart("ComputingContact")
    return [(c.Info(), c.GetProperties().Id) for c in part.Conditions]


def test_contact_property_ids(tmp_path):
    default = {properties for _, properties in _pairs(_run(tmp_path / "default"))}
    given = {properties for _, properties in _pairs(_run(tmp_path / "given", edit=_process(
        contact_property_ids={"0": 1})))}
    assert default == {100} and given == {1}


def test_process_info_keys_of_the_contact_process(tmp_path):
    """zero_tolerance_factor and active_check_factor reach the ProcessInfo, integration_order
    the properties of the pairs (where the mortar integration reads them)."""
    analysis = _run(tmp_path, edit=_process(zero_tolerance_factor=3.0, integration_order=4,
                                            search_parameters={"active_check_factor": 0.02}))
    info = analysis.model.GetModelPart("Structure").ProcessInfo
    assert info.GetValue(mc.ZERO_TOLERANCE_FACTOR) == 3.0 and info.GetValue(mc.ACTIVE_CHECK_FACTOR) == 0.02
    pair = next(iter(analysis.model.GetModelPart("Structure").GetSubModelPart("ComputingContact").Conditions))
    assert pair.GetProperties().GetValue(mc.INTEGRATION_ORDER_CONTACT) == 4


def test_normal_variation_chooses_the_conditions(tmp_path):
    """normal_variation "nodal_elemental_derivatives" and "elemental_derivatives" both build the NV
    conditions (the exact dn/du of the nodal normals; see alm_contact_process.NORMAL_DERIVATIVES);
    "elemental_derivatives" warns that it runs as the other."""
    names, logs = {}, {}
    for variation in ("no_derivatives_computation", "elemental_derivatives", "nodal_elemental_derivatives"):
        analysis, logs[variation] = _run_logged(tmp_path / variation, edit=_process(normal_variation=variation))
        names[variation] = {name for name, _ in _pairs(analysis)}
    assert names["no_derivatives_computation"] == {"ALMFrictionlessMortarContactCondition2D2N"}
    assert names["elemental_derivatives"] == names["nodal_elemental_derivatives"] == {
        "ALMNVFrictionlessMortarContactCondition2D2N"}
    warnings = [m for m in NO_EFFECT.finditer(logs["elemental_derivatives"]) if m["key"] == "normal_variation"]
    assert len(warnings) == 1 and 'runs as "nodal_elemental_derivatives"' in logs["elemental_derivatives"]
    assert "normal_variation" not in logs["nodal_elemental_derivatives"]


def test_manual_alm_parameters(tmp_path):
    analysis = _run(tmp_path, edit=_process(advance_ALM_parameters={"manual_ALM": True, "penalty": 123.0,
                                                                    "scale_factor": 4.0}))
    info = analysis.model.GetModelPart("Structure").ProcessInfo
    assert (info.GetValue(mc.INITIAL_PENALTY), info.GetValue(mc.SCALE_FACTOR)) == (123.0, 4.0)


def test_automatic_alm_parameters(tmp_path):
    def estimate(folder, **alm):
        info = _run(tmp_path / folder, edit=_process(advance_ALM_parameters=alm)).model.GetModelPart(
            "Structure").ProcessInfo
        return info.GetValue(mc.INITIAL_PENALTY), info.GetValue(mc.SCALE_FACTOR)
    penalty, scale = estimate("default")
    assert estimate("stiffer", stiffness_factor=2.0) == pytest.approx((2 * penalty, 2 * scale))
    assert estimate("scaled", penalty_scale_factor=3.0) == pytest.approx((penalty, 3 * scale))
    assert estimate("unscaled", use_scale_factor=False) == pytest.approx((penalty, 1.0))


def _search(analysis):
    assert not isinstance(analysis, Exception), analysis
    return analysis.processes[[type(p).__name__ for p in analysis.processes].index("ALMContactProcess")].searches[0]


def _shifted_contact_case(folder) -> str:
    """The contact case with the upper block moved 2 aside: its face is inside the search radius of
    the slave face but beside it."""
    path = contact_case(folder)
    mdpa = os.path.join(folder, "contact.mdpa")
    with open(mdpa) as f:
        lines = f.read().split("\n")
    nodes = range(lines.index("Begin Nodes") + 1, lines.index("End Nodes"))
    for k in nodes:
        node, x, y, z = lines[k].split()
        if int(node) in (5, 6, 7, 8):
            lines[k] = f"{node} {float(x) + 2.0} {y} {z}"
    with open(mdpa, "w") as f:
        f.write("\n".join(lines))
    return path


def test_search_keys(tmp_path):
    """The search keys, on the contact case: database_step_update (searches per step) and
    normal_orientation_threshold (no pair faces the slave) in a run; simple_search, check_gap,
    bounding_box_factor and consider_gap_threshold in searches of the finished run with the master
    face moved aside."""
    stepping = _solver(time_stepping={"time_step": 0.25})
    searched = _search(_run(tmp_path / "every", edit=stepping)).NumberOfSearches()
    rarely = _search(_run(tmp_path / "rarely", edit=lambda p: (
        stepping(p), _process(search_parameters={"database_step_update": 3})(p)))).NumberOfSearches()
    assert (searched, rarely) == (4, 2)
    assert _pairs(_run(tmp_path / "facing", edit=_process(search_parameters={"normal_orientation_threshold": 1.5}))) \
        == []
    analysis = _run(tmp_path / "aside", base=_shifted_contact_case)
    root = analysis.model.GetModelPart("Structure")
    interface = _search(analysis).InterfacePart()

    def pairs(**search):
        process = _core.ContactSearchProcess(root, interface, _core.Parameters(json.dumps(search)))
        return process.UpdateMortarConditions()["pairs"]
    radius = {"type_search": "in_radius"}
    assert pairs(**radius) == 0  # the master's projection misses the slave (mapping_check)
    assert pairs(**radius, check_gap="no_check") == pairs(**radius, simple_search=True) == 1
    assert pairs(**radius, check_gap="direct_check") == 0
    assert pairs(check_gap="no_check") == 0  # the oriented boxes are apart ...
    assert pairs(check_gap="no_check", octree_search_parameters={"bounding_box_factor": 5.0}) == 1  # ... or not
    # consider_gap_threshold drops pairs farther apart than ProcessInfo DISTANCE_THRESHOLD (1e24 unless
    # a script sets it).
    root.ProcessInfo.SetValue(mc.DISTANCE_THRESHOLD, 1e-9)
    assert pairs(**radius, check_gap="no_check", consider_gap_threshold=True) == 0


def test_normal_check_proportion(tmp_path):
    """The inverted-normal check steps normal_check_proportion x the face size off each interface
    face and flips a face that points into its element, with a warning naming it (as Kratos does); a
    step beyond the parent element cannot see it, and 0 turns the check off."""
    def inverted(folder):
        path = contact_case(folder)
        mdpa = os.path.join(folder, "contact.mdpa")
        with open(mdpa) as f:
            text = f.read()
        # The upper block's lower face, written with the node order of an inward normal.
        text = text.replace("Begin Conditions LineCondition2D2N", "Begin Conditions LineCondition2D2N")
        text += "\nBegin Conditions LineCondition2D2N\n1 0 6 5\nEnd Conditions\n"
        text += "\nBegin SubModelPart upper_face\n Begin SubModelPartNodes\n 5\n 6\n End SubModelPartNodes\n"
        text += " Begin SubModelPartConditions\n 1\n End SubModelPartConditions\nEnd SubModelPart\n"
        with open(mdpa, "w") as f:
            f.write(text)
        return path
    faces = {"contact_model_part": {"0": ["Contact_Part", "upper_face"]}}
    flipped, log = _run_logged(tmp_path / "default", base=inverted, edit=_process(**faces))
    assert not isinstance(flipped, Exception), flipped
    assert "condition 1 (nodes 6 5) points into element" in log and "flipped" in log, log
    condition = flipped.model.GetModelPart("Structure.upper_face").GetCondition(1)
    assert [node.Id for node in condition.GetNodes()] == [5, 6]
    # The flipped face duplicates a master face of Contact_Part: the displacements are those of the
    # case without it (the multipliers balance two master faces instead of one).
    def displacements(analysis):
        return [(node, values[:3]) for node, values in _nodal_values(analysis)]
    assert displacements(flipped) == displacements(_run(tmp_path / "plain"))
    _, log = _run_logged(tmp_path / "blind", base=inverted, edit=_process(**faces, normal_check_proportion=5.0))
    assert "flipped" not in log, log
    _, log = _run_logged(tmp_path / "off", base=inverted, edit=_process(**faces, normal_check_proportion=0.0))
    assert "flipped" not in log, log


def test_vtk_condition_keys(tmp_path):
    """condition_data_value_variables and condition_flags are written with the conditions."""
    def vtk(**keys):
        return lambda p: p["output_processes"]["vtk_output"][0]["Parameters"].update(entity_type="condition", **keys)
    base = _fingerprint(_run(tmp_path / "base", edit=vtk()), tmp_path / "base")["files"]
    data = _fingerprint(_run(tmp_path / "data", edit=vtk(condition_data_value_variables=["NORMAL"])),
                        tmp_path / "data")["files"]
    flags = _fingerprint(_run(tmp_path / "flags", edit=vtk(condition_flags=["SLAVE"])), tmp_path / "flags")["files"]
    assert base != data and base != flags


def test_json_check_keys(tmp_path):
    """from_json_check_result_process reads what json_output_process wrote with the same keys (node
    coordinates as names, check_for_flag selecting the nodes, integration-point values), and fails
    with the others."""
    def write(folder, **keys):
        writer = _run(tmp_path / folder, edit=lambda p: p["processes"]["json_output_process"][0]["Parameters"].update(
            **keys, output_variables=["DISPLACEMENT_X"]))
        assert not isinstance(writer, Exception), writer
        return str(tmp_path / folder / "results.json")

    def fails(reference, folder, **keys):
        item = {"python_module": "from_json_check_result_process", "kratos_module": "KratosMultiphysics",
                "Parameters": {"check_variables": ["DISPLACEMENT_X"], "input_file_name": reference,
                               "model_part_name": "Structure", "time_frequency": 0.0, **keys}}
        return isinstance(_run(tmp_path / folder, edit=lambda p: p["processes"].update(json_check_process=[item])),
                          Exception)
    by_coordinates = write("coordinates", use_node_coordinates=True)
    assert not fails(by_coordinates, "same coordinates", use_node_coordinates=True)
    assert fails(by_coordinates, "ids", use_node_coordinates=False)
    slaves = write("slaves", check_for_flag="SLAVE")
    assert not fails(slaves, "same slaves", check_for_flag="SLAVE")
    assert fails(slaves, "all nodes", check_for_flag="")
    # Wrong integration-point values fail only when gauss_points_check_variables names them.
    gauss = write("gauss", gauss_points_output_variables=["VON_MISES_STRESS"])
    assert not fails(gauss, "same gauss", gauss_points_check_variables=["VON_MISES_STRESS"])
    with open(gauss) as f:
        data = json.load(f)
    for name, values in data.items():
        if name.startswith("ELEMENT_"):
            values["VON_MISES_STRESS"] = {point: [v + 1.0 for v in series]
                                          for point, series in values["VON_MISES_STRESS"].items()}
    with open(gauss, "w") as f:
        json.dump(data, f)
    assert fails(gauss, "wrong gauss", gauss_points_check_variables=["VON_MISES_STRESS"])
    assert not fails(gauss, "nodal only", gauss_points_check_variables=[])


def test_problem_name_labels_the_summary(tmp_path):
    analysis = _run(tmp_path, edit=lambda p: p["problem_data"].update(problem_name="block on block"))
    assert analysis.Summary().startswith("block on block: 1 step")


def test_scheme_type(tmp_path):
    """scheme_type picks the implicit scheme: bossak, newmark and the BDF family (backward_euler is
    bdf1; bdf2 raises the buffer to 3) give different answers; "relaxation" is known to Kratos but
    not implemented here, plain "bdf" is no scheme (spec 2.5)."""
    def run(folder, scheme):
        analysis = _run(tmp_path / folder, base=_dense_square, edit=_solver(solver_type="Dynamic", scheme_type=scheme))
        assert not isinstance(analysis, Exception), analysis
        return analysis

    bdf2 = run("bdf2", "bdf2")
    assert bdf2.model.GetModelPart("Structure").GetBufferSize() == 3
    backward_euler = run("backward_euler", "backward_euler")
    assert _nodal_values(backward_euler) == _nodal_values(run("bdf1", "bdf1"))
    runs = (bdf2, backward_euler, run("bossak", "bossak"), run("newmark", "newmark"))
    answers = {str(_nodal_values(a)) for a in runs}
    assert len(answers) == 4
    error = _run(tmp_path / "relaxation", base=_dense_square, edit=_solver(solver_type="Dynamic",
                                                                           scheme_type="relaxation"))
    assert isinstance(error, mc.NotImplementedFeatureError) and "scheme_type" in str(error), error
    error = _run(tmp_path / "bdf", base=_dense_square, edit=_solver(solver_type="Dynamic", scheme_type="bdf"))
    assert isinstance(error, mc.InputError) and "scheme_type" in str(error), error


def test_move_mesh_flag(tmp_path):
    def moved(folder, flag):
        root = _run(tmp_path / folder, base=square_case, edit=_solver(move_mesh_flag=flag)).model.GetModelPart(
            "Structure")
        return any(abs(node.Y - node.Y0) > 1e-9 for node in root.Nodes)
    assert moved("moving", True) and not moved("fixed", False)


def test_clear_inactive_for_post(tmp_path):
    """With the gap left open the slave nodes are paired but inactive: their augmented pressure
    (penalty x weighted gap) is zeroed for the output, unless clear_inactive_for_post is false."""
    from test_bad_input import _mutated_contact_case

    def open_gap(folder):
        return _mutated_contact_case(pathlib.Path(folder), 1.05)

    def pressure(folder, clear):
        root = _run(tmp_path / folder, base=open_gap, edit=_process(
            clear_inactive_for_post=clear)).model.GetModelPart("Structure")
        return [root.GetNode(i).GetValue(mc.AUGMENTED_NORMAL_CONTACT_PRESSURE) for i in (3, 4)]
    assert pressure("cleared", True) == [0.0, 0.0]
    assert all(value != 0.0 for value in pressure("kept", False))


@pytest.mark.parametrize("spelling", ["octree_with_obb", "OctreeWithOBB"])
def test_octree_search_type_warns_naming_what_runs(tmp_path, spelling):
    """Kratos' octree search is not built here: the KD-tree search with the same oriented-box test
    runs instead, and the warning says so (issue 18)."""
    _, log = _run_logged(tmp_path, edit=_process(search_parameters={"type_search": spelling}))
    warnings = [m for m in NO_EFFECT.finditer(log) if m["key"] == "type_search"]
    assert len(warnings) == 1 and f'"{spelling}"' in warnings[0]["value"], log
    assert "'in_radius_with_obb'" in log


def test_problem_data_echo_level_prints_the_steps(tmp_path, capsys):
    _run(tmp_path / "quiet")
    assert "STEP 1" not in capsys.readouterr().out
    _run(tmp_path / "verbose", edit=lambda p: p["problem_data"].update(echo_level=1))
    assert "STEP 1  TIME 1" in capsys.readouterr().out
