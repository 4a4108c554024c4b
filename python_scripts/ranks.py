"""The ranks of a model cut across processes (``MORTARCONTACT_PARTITIONED_MODEL=1`` under mpirun):
what the processes reporting on the whole model need to put the ranks' pieces back together."""
from __future__ import annotations

import pickle

import numpy as np

from . import _core


class Ranks:
    """The processes sharing the linear solver's communicator, each holding its piece of the model.
    A node is reported by the rank that owns it, an element by the owner of its first node (each
    rank keeps the elements touching its nodes, so the owner holds it): every entity once."""

    def __init__(self, linear_solver):
        self._linear_solver = linear_solver
        self.rank = _core.LaunchedRank()
        self.size = linear_solver.Processes()

    def all_gather(self, value) -> list:
        """Collective: every rank's ``value`` (picklable), in rank order, on every rank."""
        return [pickle.loads(data) for data in _core.AllGather(self._linear_solver, pickle.dumps(value))]

    def stop_together(self, action) -> None:
        """Collective: runs ``action``; when it raised a user's error (InputError or
        NotImplementedFeatureError) on any rank, every rank raises the lowest such rank's, so no
        rank is left waiting in the next collective and rank 0 prints that one message."""
        errors = (_core.InputError, _core.NotImplementedFeatureError)
        try:
            action()
            mine = None
        except errors as error:
            mine = (int(isinstance(error, errors[1])), str(error))
        failed = [error for error in self.all_gather(mine) if error is not None]
        if failed:
            kind, message = failed[0]
            raise errors[kind](message)

    def owned_nodes(self, part) -> np.ndarray:
        """Whether this rank owns each node of ``part``, in node-id order."""
        return _core.OwnedNodes(part)

    def owned_node_ids(self, part) -> set[int]:
        """The ids of the nodes of ``part`` this rank owns."""
        return set(part.NodeIds()[self.owned_nodes(part)].tolist())

    def owned_elements(self, part) -> set[int]:
        """The ids of the elements of ``part`` this rank reports."""
        owned = self.owned_node_ids(part)
        return {element.Id for element in part.Elements if element.NodeIds()[0] in owned}
