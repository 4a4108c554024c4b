"""What every mortar contact process does (spec 4.1-4.3): read the interface slots, build the
interface and one contact search per slot, run the searches inside the interval."""
from __future__ import annotations

from .. import _core
from ..process import Process
from ..processes.model_part_resolution import resolve_model_part
from ..utilities import warn
from . import _settings
from .initial_overlap import check_initial_overlap

#: Why consider_tessellation (a Delaunay instead of a fan triangulation of the clipped overlap
#: polygons, spec 4.2) is not followed (issue 18): the overlap polygons are convex, and their
#: integrands are polynomials on triangular faces (smooth on quadrilateral ones), so every
#: triangulation integrates them alike to the quadrature's accuracy; Delaunay only pays off on
#: non-convex cells, which clipping never makes. The fan has one more merit for the exact tangent
#: (MortarPairKinematics differentiates through the cells): its cells keep their topology as the
#: mesh moves, while a Delaunay triangulation flips an edge whenever four vertices pass through a
#: common circle, making D and M only piecewise smooth.
TESSELLATION_WITHOUT_EFFECT = ("the overlap polygons are convex, so the fan triangulation integrates them as a "
                               "Delaunay one would, and it keeps the exact tangent smooth (no edge flips as the mesh "
                               "moves)")


class SearchBaseProcess(Process):
    """Base of the ALM, penalty and mesh-tying processes: interface set-up and contact search."""

    python_module = ""
    #: The slot keys are "<pair_prefix>_model_part" and "<pair_prefix>_property_ids" (spec 4.1).
    pair_prefix = "contact"

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        return _settings.to_parameters(_settings.alm_defaults())

    def __init__(self, model, settings=None):
        settings = settings if settings is not None else _core.Parameters()
        _settings.normalise_pair_layouts(
            settings, ("contact_model_part", "assume_master_slave", "contact_property_ids", "friction_coefficients"))
        self.model = model
        self.settings = settings
        self.settings.RecursivelyValidateAndAssignDefaults(self.GetDefaultParameters())
        self.interval = _settings.interval_of(self.settings)
        self._init_search_state()
        self._check_types()
        self._check_factors()
        _core.NoEffectWarnings.IfGiven(self.settings, self.GetDefaultParameters(), "consider_tessellation",
                                       TESSELLATION_WITHOUT_EFFECT)

    # Settings ----------------------------------------------------------------------------------
    def _check_types(self) -> None:
        """Hook: reject the contact types this class does not implement."""

    def _check_factors(self) -> None:
        """Factors that scale distances must be positive numbers (issue 16: a negative one was
        accepted and silently found no contact)."""
        sp = self.settings["search_parameters"]
        for block, key in ((sp, "active_check_factor"), (sp, "search_factor"),
                           (self.settings, "zero_tolerance_factor")):
            value = block[key].GetDouble()
            if not 0.0 < value < float("inf"):
                raise _core.InputError(f"{block.Where()}.{key}: must be a positive number, got {value!r}")

    def interface_slots(self) -> list[tuple[str, list[str], list[str], int, float]]:
        """(slot, parts, slave parts, property id, friction coefficient) of the non-empty slots;
        all empty -> one slot over the skin of the whole model (spec 4.1)."""
        parts, slaves = self.settings[f"{self.pair_prefix}_model_part"], self.settings["assume_master_slave"]
        ids = self.settings[f"{self.pair_prefix}_property_ids"]

        def mu(slot: str) -> float:  # mesh tying has no friction coefficients
            mus = self.settings["friction_coefficients"] if self.settings.Has("friction_coefficients") else None
            return mus[slot].GetDouble() if mus is not None else 0.0

        slots = []
        for slot in _settings.SLOTS:
            names = parts[slot].GetStringArray()
            if names:
                slots.append((slot, names, slaves[slot].GetStringArray(), ids[slot].GetInt(), mu(slot)))
        if not slots:
            slots.append(("0", [], slaves["0"].GetStringArray(), ids["0"].GetInt(), mu("0")))
        return slots

    def _init_search_state(self) -> None:
        self.searches = []
        #: (STEP, statistics of UpdateMortarConditions) of every search so far, slot after slot
        self.search_statistics = []
        self.root = None
        self._steps_since_search = None
        self._inside = None

    # Hooks ---------------------------------------------------------------------------------------
    def ExecuteInitialize(self) -> None:
        self.root = resolve_model_part(self.model, self.settings["model_part_name"].GetString())
        self.check_solver_variables()
        info = self.root.GetProcessInfo()
        sp = self.settings["search_parameters"]
        if not info.Has(_core.DISTANCE_THRESHOLD):
            info.SetValue(_core.DISTANCE_THRESHOLD, 1.0e24)
        info.SetValue(_core.ZERO_TOLERANCE_FACTOR, self.settings["zero_tolerance_factor"].GetDouble())
        builder = _core.ContactInterfaceBuilder(self.root)
        interfaces = []
        for slot, parts, slaves, property_id, mu in self.interface_slots():
            interface = builder.Build(slot, parts, slaves, property_id, mu,
                                      self.settings["normal_check_proportion"].GetDouble())
            check_initial_overlap(interface, slot)
            interfaces.append((slot, interface, slaves, mu))
        if sp.Has("adapt_search") and sp["adapt_search"].GetBool():  # mesh tying has no adapt_search
            self._adapt_search([interface for _, interface, _, _ in interfaces])
        info.SetValue(_core.ACTIVE_CHECK_FACTOR, sp["active_check_factor"].GetDouble())
        for slot, interface, slaves, mu in interfaces:
            properties = _core.ContactInterfaceBuilder.InterfaceProperties(self.root, slot)
            self._check_friction_coefficient(slot, mu, properties)
            properties.SetValue(_core.INTEGRATION_ORDER_CONTACT, self.settings["integration_order"].GetInt())
            properties.SetValue(_core.ACTIVE_CHECK_FACTOR, sp["active_check_factor"].GetDouble())
            self.searches.append(_core.ContactSearchProcess(
                self.root, interface, sp, slot=slot, condition_name=self.condition_stem,
                predefined_master_slave=bool(slaves), property_id=properties.Id))

    @classmethod
    def parts_kept_whole(cls, settings) -> list[str] | None:
        """The parts the interfaces are built from (``<pair_prefix>_model_part``); None for the skin
        of the whole model (every slot empty) or settings the constructor will reject. The slave
        parts (``assume_master_slave``) need not be whole: only their nodes on the interface count."""
        key = f"{cls.pair_prefix}_model_part"
        settings = settings.Clone()
        _settings.normalise_pair_layouts(settings, (key,))
        if not settings.Has(key) or not settings[key].IsSubParameter():
            return None
        try:
            names = [name for slot in settings[key].Keys() for name in settings[key][slot].GetStringArray()]
        except _core.InputError:
            return None
        return names or None

    def ExecuteBeforeModelCut(self, bodies) -> list:
        # Every rank searches the whole interface (the pairs reach master faces anywhere) and
        # computes every pair, so the pairs' part is replicated too.
        for search in self.searches:
            if bodies is None:
                search.FindBodies()
            else:
                search.SetBodies(*bodies)
        return [part for search in self.searches for part in (search.InterfacePart(), search.ComputingPart())]

    def _adapt_search(self, interfaces) -> None:
        """adapt_search (spec 4.3): search_factor and active_check_factor times the ratio of the
        largest to the smallest NODAL_H, as Kratos does. Kratos takes the ratio over every node of
        the model; NODAL_H exists here on the interface nodes only, and the interface is what the
        search and the prediction measure."""
        lengths = []
        for interface in interfaces:
            historical = interface.HasNodalSolutionStepVariable(_core.NODAL_H)
            values = (interface.GetNodalValues(_core.NODAL_H) if historical
                      else interface.GetNodalNonHistoricalValues(_core.NODAL_H))
            lengths.extend(float(v) for v in values)
        if not lengths or min(lengths) <= 0.0:
            return
        factor = max(lengths) / min(lengths)
        sp = self.settings["search_parameters"]
        for key in ("search_factor", "active_check_factor"):
            sp[key].SetDouble(sp[key].GetDouble() * factor)
        warn(f"{sp.Where()}.adapt_search: search_factor and active_check_factor scaled by the interface's "
             f"largest / smallest NODAL_H = {factor:.3g}, to {sp['search_factor'].GetDouble():.3g} and "
             f"{sp['active_check_factor'].GetDouble():.3g}")

    def _check_friction_coefficient(self, slot: str, mu: float, properties) -> None:
        """friction_coefficients[k] only fills a property without FRICTION_COEFFICIENT (spec 4.1):
        say so when the materials' value wins over a different one given here."""
        used = properties.GetValue(_core.FRICTION_COEFFICIENT)
        if mu != 0.0 and used != mu:
            warn(f"{self.settings['friction_coefficients'].Where()}.{slot}: {mu!r} is not used: the interface "
                 f"property {properties.Id} already has FRICTION_COEFFICIENT {used!r} (from the materials)")

    def check_solver_variables(self) -> None:
        """Hook: the start-up check of the mortar_type pairing (spec 2.10)."""

    def _check_mortar_type(self, chosen_by: str) -> None:
        """The solver registers its formulation before the mesh is read (spec 2.10): this process's,
        chosen by `chosen_by` (its key and value, for the message), must be the same."""
        solver = self.root.GetProcessInfo().GetValue(_core.MORTAR_TYPE)
        if solver != self.formulation.mortar_type:
            found = f"\"{solver}\"" if solver else "none (a solver without contact_settings)"
            raise _core.InputError(
                f"{self.python_module} with {chosen_by} needs "
                f"solver_settings.contact_settings.mortar_type \"{self.formulation.mortar_type}\"; found {found}")

    def ExecuteInitializeSolutionStep(self) -> None:
        info = self.root.GetProcessInfo()
        time = info.GetValue(_core.TIME)
        start, end = self.interval
        inside = start - 1e-12 <= time <= end + 1e-12
        if not inside:
            if self._inside is not False:
                for search in self.searches:
                    search.ClearMortarConditions()
                    search.SetInterfaceActive(False)
            self._inside = False
            self._steps_since_search = None
            return
        if self._inside is False:
            for search in self.searches:
                search.SetInterfaceActive(True)
        self._inside = True
        update = max(1, self.settings["search_parameters"]["database_step_update"].GetInt())
        if self._steps_since_search is None or self._steps_since_search >= update:
            step = info.GetValue(_core.STEP)
            for search in self.searches:
                self.search_statistics.append((step, search.UpdateMortarConditions()))
            self._steps_since_search = 0
        self._steps_since_search += 1

    def RestartState(self):
        return {"steps_since_search": self._steps_since_search}

    def LoadRestartState(self, state) -> None:
        """The contact pairs are not in a checkpoint: the first resumed step searches. With
        database_step_update > 1 the uninterrupted run may have reused older pairs there."""
        update = max(1, self.settings["search_parameters"]["database_step_update"].GetInt())
        since = state["steps_since_search"]
        if since is not None and since < update:
            warn(f"{self.python_module}: database_step_update is {update}: the resumed run searches at its first "
                 f"step, where the uninterrupted run would have reused the pairs of {since} step(s) before; "
                 "the results differ slightly")

    def ExecuteFinalizeSolutionStep(self) -> None:
        # Here rather than before the output (as Kratos clears): the json processes read the
        # step's values in their own ExecuteFinalizeSolutionStep, after this one.
        if self.root is not None:
            _core.ComputeContactOutputs(self.root.GetSubModelPart("Contact"),
                                        self.settings["clear_inactive_for_post"].GetBool())

