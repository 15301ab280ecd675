"""Complex mode shapes of a pair for NVH tools: the Universal File Format, written by pyuff.

`write_modes_uff(problem, modes, path)` writes the nodes (dataset 2411: node numbers from 1, the
slave's first, coordinates in m) and one dataset 55 per mode (data at nodes: complex eigenvalue
analysis of the displacement, analysis type 3; the eigenvalue ``s`` [rad/s]; the shape's x, y, z
complex components at every node, a 2-D body's z = 0, normalised to a largest displacement of 1).
Dataset 55 is where the format keeps mode shapes; dataset 58 keeps functions of time or frequency
(a response, an FRF) and has no place for a shape. Its numbers are written with six significant
digits (the format's ``E13.5``).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..errors import ParameterError
from .cea import CeaModes
from .pair import PairProblem

__all__ = ["write_modes_uff"]


def write_modes_uff(problem: PairProblem, modes: CeaModes, path) -> Path:
    """Write ``modes`` (with shapes) of ``problem`` to the UFF file ``path`` (see the module
    docstring); returns ``path``. The file is written whole or not at all."""
    import pyuff

    if not isinstance(problem, PairProblem):
        raise ParameterError("problem", problem, "a stickslip.fem.PairProblem")
    if not isinstance(modes, CeaModes) or modes.shapes is None:
        raise ParameterError("modes", type(modes).__name__, "CeaModes with shapes (mode_shapes=True)")
    if not isinstance(path, (str, os.PathLike)):
        raise ParameterError("path", path, "a new .uff or .unv file in an existing folder (a path)")
    path = Path(path)
    if path.suffix.lower() not in (".uff", ".unv") or path.is_dir() or not path.parent.is_dir():
        raise ParameterError("path", str(path), "a new .uff or .unv file in an existing folder")
    dim = problem.dimension
    points = np.vstack([problem.slave.body.points, problem.master.body.points])
    if dim == 2:
        points = np.column_stack([points, np.zeros(len(points))])
    shapes = problem.displacements(modes.shapes)
    nodes = np.arange(1, len(points) + 1)
    sets = [pyuff.prepare_2411(node_nums=nodes, def_cs=np.ones(len(nodes), int), disp_cs=np.ones(len(nodes), int),
                               color=np.ones(len(nodes), int), x=points[:, 0], y=points[:, 1], z=points[:, 2],
                               return_full_dict=True)]
    for k, s in enumerate(modes.s):
        u = shapes[:, k]
        u = (u / np.abs(u).max()).reshape(-1, dim)
        r3 = u[:, 2] if dim == 3 else np.zeros(len(points), complex)
        sets.append(pyuff.prepare_55(id1=f"stickslip CEA mode {k}", id2=f"growth rate {s.real:.6g} 1/s",
                                     id3=f"frequency {s.imag / (2 * np.pi):.6g} Hz", id4="NONE", id5="NONE",
                                     model_type=1, analysis_type=3, data_ch=2, spec_data_type=8, data_type=5,
                                     n_data_per_node=3, load_case=1, mode_n=k + 1, eig=complex(s),
                                     modal_a=0j, modal_b=0j, node_nums=nodes, r1=u[:, 0], r2=u[:, 1], r3=r3))
        # (not return_full_dict: its empty r4-r6 would make pyuff write six values per node)
    partial = path.with_name(path.name + ".partial")
    partial.unlink(missing_ok=True)
    pyuff.UFF(str(partial)).write_sets(sets, mode="overwrite")
    partial.replace(path)
    return path
