"""ParaView output of a general body: run snapshots and CEA mode shapes as XDMF time series.

Both write the body's mesh (points at ``z = 0``, in m) with `stickslip.files.write_xdmf_series`
(the ``.xdmf`` and its ``.h5`` beside it; `meshio.xdmf.TimeSeriesReader` reads them back).

* `write_run_xdmf(run, path)`: the volume snapshots of `integrate_body(..., volume_every=T)`
  (or of `stickslip.fem.pair_run.integrate_pair`: both bodies in one mesh, the slave's points
  first, with the point data ``body``, 0 the slave and 1 the master, and ``material`` counting
  the slave's materials first; of two solids, Cartesian x, y, z, ``contact_shear_cross`` across the sliding
  direction too, and the cells' ``stress_xx`` ... ``stress_xy`` in Voigt order, ``von_mises`` and ``material``:
  `stickslip.fem.solid_stress`);
  per snapshot (time [s]) the point data ``displacement`` [m] (total, from the unstressed
  body), ``velocity`` [m/s], and on the contact nodes ``contact_pressure`` and
  ``contact_shear`` [N per unit thickness per node] and ``contact_state`` (0 stick, 1 slip,
  2 reverse slip, 3 separation; -1 off the contact line); the cell data ``stress_xx``,
  ``stress_yy``, ``stress_xy`` and ``von_mises`` [Pa] (cell means, `stickslip.fem.assembly.cell_stress` and
  `stickslip.fem.assembly.von_mises`: in plane strain with ``sigma_zz = nu (sigma_xx + sigma_yy)``) and
  ``material`` (each cell's material, its position in the problem's ``material_groups``).
* `write_modes_xdmf(problem, modes, path)`: the shapes of the CEA modes
  (`complex_eigenvalues(..., mode_shapes=True)`; of a pair of bodies too, both meshes in one
  with the point data ``body``, 0 the slave and 1 the master), one step per mode (the step's "time" is the
  mode's index in ``modes``, most unstable first): ``mode_real``, ``mode_imag`` (the complex
  shape, normalised to a largest displacement of 1: ``Re(w e^(i phi))`` animates it), ``mode_amplitude``
  and, constant over the mesh, ``growth_rate`` [1/s] and ``frequency`` [Hz]. Vectors are Cartesian, a
  2-D body's padded with ``z = 0``; a pair of solids is written in 3-D (its reduced CEA's modes too,
  `stickslip.fem.reduced`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import ParameterError
from ..files import write_xdmf_series
from .assembly import cell_stress, von_mises
from .cea import CeaModes, linearised
from .pair_run import PairRun
from .run import BodyRun
from .scheme import BodyScheme, ContactProblem

__all__ = ["write_run_xdmf", "write_modes_xdmf", "run_snapshot"]


def _mesh(body):
    """Points ``(n, 3)`` (a 2-D body's at ``z = 0``) and the cell block of a body or a solid."""
    points = body.points if body.points.shape[1] == 3 else np.column_stack([body.points, np.zeros(len(body.points))])
    return points, [(body.kind, body.cells.astype(np.int64))]


def _vectors(xy: np.ndarray, dim: int = 2) -> np.ndarray:
    """``(dim n,)`` Cartesian dof values -> ``(n, 3)`` vectors."""
    xy = np.asarray(xy).reshape(-1, dim)
    return xy if dim == 3 else np.column_stack([xy, np.zeros(len(xy), dtype=xy.dtype)])


def write_run_xdmf(run: BodyRun | PairRun, path) -> Path:
    """Write the volume snapshots of ``run`` (see the module docstring); returns ``path``."""
    if not isinstance(run, (BodyRun, PairRun)):
        raise ParameterError("run", type(run).__name__, "a BodyRun or a PairRun (from integrate_body, integrate_pair)")
    snaps = run.snapshots
    if not run.settings.get("volume_every") or len(snaps.get("vol_t", ())) == 0:
        raise ParameterError("run", "a run without volume snapshots", "a run integrated with volume_every=T")
    if isinstance(run, PairRun):
        return _pair_run(run, path)
    body = run.scheme.problem.system.body
    steps = (run_snapshot(run.scheme, snaps, k) for k in range(len(snaps["vol_t"])))
    return write_xdmf_series(path, *_mesh(body), steps)


def run_snapshot(scheme: BodyScheme, snapshots: dict, k: int) -> tuple[float, dict, dict]:
    """``(time, point_data, cell_data)`` of volume snapshot ``k`` of a run of ``scheme`` (see the
    module docstring; a specialisation such as the paper's annulus adds its own fields to these)."""
    system = scheme.problem.system
    body, frames = system.body, scheme.problem.frames
    nodes = frames.nodes[scheme.contact_nodes]
    n = len(body.points)

    def on_line(values):
        out = np.zeros(n)
        out[nodes] = values
        return out

    state = np.full(n, -1, dtype=np.int32)
    state[nodes] = snapshots["vol_state"][k]
    u = scheme.cartesian(snapshots["vol_u"][k])
    point_data = {"displacement": _vectors(u), "velocity": _vectors(scheme.cartesian(snapshots["vol_v"][k])),
                  "contact_pressure": on_line(snapshots["vol_P"][k]), "contact_shear": on_line(snapshots["vol_Q"][k]),
                  "contact_state": state}
    sigma = cell_stress(system, u)
    sxx, syy, sxy = sigma.T
    cell_data = {"stress_xx": [sxx], "stress_yy": [syy], "stress_xy": [sxy], "von_mises": [von_mises(system, sigma)],
                 "material": [system.cell_material.astype(np.int32)]}  # its position in material_groups
    return float(snapshots["vol_t"][k]), point_data, cell_data


def _both(problem):
    """Both meshes of a pair in one (the slave's points first): points, cell blocks, and the
    point data ``body`` (0: slave, 1: master)."""
    s_body, m_body = problem.slave.body, problem.master.body
    points = np.vstack([_mesh(s_body)[0], _mesh(m_body)[0]])
    cells = [(s_body.kind, s_body.cells.astype(np.int64)), (m_body.kind, m_body.cells.astype(np.int64) + len(s_body.points))]
    which = np.concatenate([np.zeros(len(s_body.points)), np.ones(len(m_body.points))]).astype(np.int32)
    return points, cells, which


def _pair_run(run: PairRun, path) -> Path:
    """The volume snapshots of a run of a pair of bodies (`write_run_xdmf`; of solids, their cells' six
    stresses, and ``contact_shear_cross`` across the sliding)."""
    scheme, snaps = run.scheme, run.snapshots
    p = scheme.params
    points, cells, which = _both(p)
    dim = p.dimension
    n, ns = len(points), dim * len(p.slave.body.points)
    nodes = scheme.contact_nodes
    if dim == 3:
        from .solid_stress import solid_cell_material, solid_stress, solid_von_mises

        materials = [solid_cell_material(p.slave), solid_cell_material(p.master) + len(p.slave.materials)]
    else:
        materials = [p.slave.cell_material.astype(np.int32),
                     (p.master.cell_material + len(p.slave.materials)).astype(np.int32)]

    def on_line(values, fill=0.0, dtype=float):
        out = np.full(n, fill, dtype=dtype)
        out[nodes] = values
        return out

    def step(k):
        u = scheme.cartesian(snaps["vol_u"][k])
        point_data = {"displacement": _vectors(u, dim), "velocity": _vectors(scheme.cartesian(snaps["vol_v"][k]), dim),
                      "contact_pressure": on_line(snaps["vol_P"][k]), "contact_shear": on_line(snaps["vol_Q"][k]),
                      "contact_state": on_line(snaps["vol_state"][k], -1, np.int32), "body": which}
        if "vol_Q_cross" in snaps:
            point_data["contact_shear_cross"] = on_line(snaps["vol_Q_cross"][k])
        if dim == 3:  # the six stresses and von Mises of each cell (its mean, `stickslip.fem.solid_stress`)
            names = ("stress_xx", "stress_yy", "stress_zz", "stress_yz", "stress_xz", "stress_xy")
            cell_data = {name: [] for name in (*names, "von_mises")}
            for system, part in ((p.slave, u[:ns]), (p.master, u[ns:])):
                sigma = solid_stress(system, part)
                for name, values in zip(names, sigma.T):
                    cell_data[name].append(values)
                cell_data["von_mises"].append(solid_von_mises(sigma))
            cell_data["material"] = materials
            return float(snaps["vol_t"][k]), point_data, cell_data
        cell_data = {name: [] for name in ("stress_xx", "stress_yy", "stress_xy", "von_mises")}
        for system, part in ((p.slave, u[:ns]), (p.master, u[ns:])):
            sigma = cell_stress(system, part)
            for name, values in zip(("stress_xx", "stress_yy", "stress_xy"), sigma.T):
                cell_data[name].append(values)
            cell_data["von_mises"].append(von_mises(system, sigma))
        cell_data["material"] = materials
        return float(snaps["vol_t"][k]), point_data, cell_data

    return write_xdmf_series(path, points, cells, (step(k) for k in range(len(snaps["vol_t"]))))


def _pair_modes(problem, modes: CeaModes, path) -> Path:
    """The mode shapes of a pair of bodies: both meshes in one (`_both`)."""
    points, cells, which = _both(problem)
    n, dim = len(points), problem.dimension
    shapes = problem.displacements(modes.shapes)

    def step(k):
        u = shapes[:, k] / np.abs(shapes[:, k]).max()
        amplitude = np.sqrt(np.sum(np.abs(u.reshape(-1, dim)) ** 2, axis=1))
        return float(k), {"mode_real": _vectors(u.real, dim), "mode_imag": _vectors(u.imag, dim),
                          "mode_amplitude": amplitude,
                          "growth_rate": np.full(n, modes.growth_rate[k]), "frequency": np.full(n, modes.frequency[k]),
                          "body": which}, {}

    return write_xdmf_series(path, points, cells, (step(k) for k in range(len(modes.s))))


def write_modes_xdmf(problem: ContactProblem, modes: CeaModes, path) -> Path:
    """Write the shapes of ``modes`` of ``problem`` (see the module docstring); returns ``path``.
    ``problem`` may be a `stickslip.fem.pair.PairProblem`: both bodies in one mesh."""
    if not isinstance(modes, CeaModes) or modes.shapes is None:
        raise ParameterError("modes", type(modes).__name__, "CeaModes from complex_eigenvalues(..., mode_shapes=True)")
    if not isinstance(problem, ContactProblem):
        return _pair_modes(problem, modes, path)
    scheme = BodyScheme(problem)
    params = modes.params or {}
    _, _, _, kept = linearised(problem, params.get("mass_matrix", "lumped"), params.get("contact_model", "constraint"),
                               params.get("penalty"))
    body = problem.system.body
    n = len(body.points)

    def step(k):
        w = np.zeros(scheme.free.size, dtype=complex)
        w[kept] = modes.shapes[:, k]
        u = scheme.cartesian(w.real) + 1j * scheme.cartesian(w.imag)
        u = u / np.abs(u).max()
        amplitude = np.hypot(np.abs(u[0::2]), np.abs(u[1::2]))
        return float(k), {"mode_real": _vectors(u.real), "mode_imag": _vectors(u.imag), "mode_amplitude": amplitude,
                          "growth_rate": np.full(n, modes.growth_rate[k]),
                          "frequency": np.full(n, modes.frequency[k])}, {}

    return write_xdmf_series(path, *_mesh(body), (step(k) for k in range(len(modes.s))))
