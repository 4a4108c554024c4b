"""``impose_rigid_movement_process`` (StructuralMechanicsApplication): the nodes of a part move with
one of them. For every other node n of ``model_part_name`` (below ``main_model_part_name``) and
every component of ``master_variable_name`` (a vector variable gives its X, Y and, in 3D, Z), a
master-slave constraint

    slave_variable(n) = relation * master_variable(master) + constant

ties it to the master node (``master_node_id``, or the part's first node when 0). The builders
eliminate the constraints (``BuilderAndSolver``: T^T K T), so they hold exactly after every solve;
they are active inside ``interval``. ``new_model_part_name`` names the sub part that lists the
constraints (created under the part; default: the part itself).
"""
from __future__ import annotations

from .. import _core
from ..process import Process
from ._assignment import Interval, current_time, defaults, to_python
from .bulk_data import is_array3, is_scalar, variable_by_name
from .model_part_resolution import resolve_model_part


def _components(name: str, domain_size: int, where: str, key: str) -> list:
    """The double variables a name stands for: itself, or the components of a vector variable."""
    try:
        variable = variable_by_name(name)
    except _core.InputError as error:
        raise _core.InputError(f"{where}.{key}: {error}") from None
    if is_scalar(variable):
        return [variable]
    if is_array3(variable):
        return [variable_by_name(f"{name}_{axis}") for axis in "XYZ"[:domain_size]]
    raise _core.InputError(f"{where}.{key}: '{name}' is neither a double, a component nor a vector variable")


class ImposeRigidMovementProcess(Process):
    @classmethod
    def GetDefaultParameters(cls):
        return defaults("""{
            "help": "", "main_model_part_name": "Structure", "model_part_name": "please_specify_model_part_name",
            "new_model_part_name": "", "interval": [0.0, 1e30], "master_variable_name": "DISPLACEMENT",
            "slave_variable_name": "", "relation": 1.0, "constant": 0.0, "master_node_id": 0}""")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        s = self.settings
        self.where = s.Where()
        self.interval = Interval(to_python(s["interval"]), f"{self.where}.interval")
        main = resolve_model_part(model, s["main_model_part_name"].GetString())
        name = s["model_part_name"].GetString()
        self.part = resolve_model_part(model, name if "." in name else f"{main.FullName()}.{name}")
        new_name = s["new_model_part_name"].GetString()
        if new_name and new_name != self.part.Name:
            self.rigid_part = (self.part.GetSubModelPart(new_name) if self.part.HasSubModelPart(new_name)
                               else self.part.CreateSubModelPart(new_name))
            self.rigid_part.AddNodes([node.Id for node in self.part.Nodes])
        else:
            self.rigid_part = self.part
        domain_size = main.ProcessInfo.GetValue(_core.DOMAIN_SIZE) or 3
        self.masters = _components(s["master_variable_name"].GetString(), domain_size, self.where,
                                   "master_variable_name")
        slave_name = s["slave_variable_name"].GetString()
        self.slaves = (_components(slave_name, domain_size, self.where, "slave_variable_name") if slave_name
                       else self.masters)
        if len(self.slaves) != len(self.masters):
            raise _core.InputError(f"{self.where}: master_variable_name and slave_variable_name have "
                                   f"{len(self.masters)} and {len(self.slaves)} components")
        self.constraints = []

    def ExecuteInitialize(self) -> None:
        s = self.settings
        nodes = list(self.rigid_part.Nodes)
        if not nodes:
            raise _core.InputError(f"{self.where}.model_part_name: {self.rigid_part.FullName()} has no nodes")
        master_id = s["master_node_id"].GetInt()
        if master_id == 0:
            master = nodes[0]
        else:
            root = self.rigid_part.GetRootModelPart()
            if not root.HasNode(master_id):
                raise _core.InputError(f"{self.where}.master_node_id: no node {master_id} in {root.Name}")
            master = root.GetNode(master_id)
        relation, constant = s["relation"].GetDouble(), s["constant"].GetDouble()
        root = self.rigid_part.GetRootModelPart()
        next_id = len(root.MasterSlaveConstraints) + 1
        for node in nodes:
            if node.Id == master.Id:
                continue
            for master_variable, slave_variable in zip(self.masters, self.slaves):
                constraint = _core.MasterSlaveConstraint(next_id, node.GetDof(slave_variable),
                                                         [master.GetDof(master_variable)], [relation], constant)
                next_id += 1
                self.rigid_part.AddMasterSlaveConstraint(constraint)
                self.constraints.append(constraint)

    def ExecuteInitializeSolutionStep(self) -> None:
        active = self.interval.contains(current_time(self.rigid_part))
        for constraint in self.constraints:
            constraint.SetActive(active)


#: python_module -> class, registered under StructuralMechanicsApplication by the process factory
STRUCTURAL_PROCESSES = {"impose_rigid_movement_process": ImposeRigidMovementProcess}
