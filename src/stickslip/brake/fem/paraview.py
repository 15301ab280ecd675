"""ParaView output of an FE run: the mesh and its volume snapshots as an XDMF time series.

`write_xdmf(run, path)` writes the volume snapshots that `integrate_fem(..., volume_every=T)`
keeps (see `FemRun`) with meshio's ``xdmf.TimeSeriesWriter``: ``path`` (``.xdmf``, XML) and
its HDF5 companion ``path.with_suffix(".h5")`` beside it, which ParaView opens (XDMF reader;
it shows meshio's layout as two blocks, the time series and the static ``mesh``) and
``meshio.xdmf.TimeSeriesReader`` reads back.

Units are the paper's: points and displacements in units of ``R`` (the bore radius), so the
mesh is the annulus ``1 <= r <= xi`` at ``z = 0``; velocities in ``R Omega``; stresses,
pressures and tractions in units of ``E``; times in seconds (the snapshot times ``vol_t`` of the
run, ``Omega t̄``, divided by ``Omega``), as in the run's netCDF and in `stickslip fem`'s XDMF;
a run of dimensionless parameters (`BrakeParams` without physical ones) has no seconds and keeps
the paper's ``Omega t̄``. XDMF has no place for units, hence this list. Vectors
are Cartesian and padded with ``z = 0`` (ParaView's 3-component vectors). The fields are the
general body's (`stickslip.fem.paraview.run_snapshot`, on the annulus's problem
`problem.annulus_problem`) and the annulus's polar components beside them. Per snapshot:

point data (every node of the mesh, the clamped ring ``r = xi`` included, where ``u = 0``)
    ``displacement``: total displacement from the unstressed ring (steady shrink fit plus
    the motion), ``u_r``, ``u_theta``: its polar components, ``velocity``: the scheme's
    velocity ``v_m`` at the snapshot time;
    on the contact surface ``r = 1``: ``contact_pressure`` ``p`` (>= 0, compression),
    ``contact_shear`` ``q`` (friction, positive along the shaft's motion, ``+theta``),
    ``contact_traction`` ``p e_r + q e_theta`` (the shaft's traction on the ring) and
    ``contact_state`` (`stickslip.contact.STATE_NAMES`: 0 stick, 1 slip, 2 reverse slip,
    3 separation); away from ``r = 1`` pressure, shear and traction are 0, the state -1.
cell data (the mean over each quadrilateral of the FE stress, plane strain: the general body's
`stickslip.fem.assembly.cell_stress` of the nodal displacement)
    ``stress_xx``, ``stress_yy``, ``stress_xy``, ``von_mises`` (`stickslip.fem.assembly.von_mises`)
    and ``material`` (0: the one material); ``stress``: the Cartesian tensor, 9 components row
    by row (``xx xy xz yx yy yz zx zy zz``, ``sigma_zz = nu (sigma_xx + sigma_yy)``);
    ``sigma_rr``, ``sigma_thth``, ``sigma_rth``: its polar components at the cell's centre angle.

The files are written in a hidden temporary folder beside ``path`` (removed afterwards, or
left behind by a killed process) and moved into place, the ``.h5`` first, then the
``.xdmf``: an interrupted write leaves no partial file under either name (only a kill between
the two moves would pair an older ``.xdmf`` with the new ``.h5``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ...errors import ParameterError
from ...fem.paraview import run_snapshot
from ...files import write_xdmf_series
from .run import FemRun

__all__ = ["write_xdmf"]


def _polar(scheme, snapshots: dict, k: int) -> tuple[float, dict, dict]:
    """The general body's fields of snapshot ``k`` and the annulus's polar components beside them
    (the displacement's exactly as the run holds them: its dofs are polar)."""
    time, points, cells = run_snapshot(scheme, snapshots, k)
    p = scheme.problem.system.body.points
    ang = np.arctan2(p[:, 1], p[:, 0])
    c, s = np.cos(ang), np.sin(ang)
    polar = np.zeros(2 * len(p))
    polar[scheme.free] = snapshots["vol_u"][k]
    pressure, shear = points["contact_pressure"], points["contact_shear"]
    traction = np.column_stack([c * pressure - s * shear, s * pressure + c * shear, np.zeros_like(c)])
    points = {**points, "u_r": polar[0::2], "u_theta": polar[1::2],
              "contact_traction": traction}
    sxx, syy, sxy = cells["stress_xx"][0], cells["stress_yy"][0], cells["stress_xy"][0]
    szz = scheme.params.nu * (sxx + syy)  # plane strain: lambda (eps_xx + eps_yy), E = 1
    zero = np.zeros_like(sxx)
    centre = p[scheme.problem.system.body.cells].mean(axis=1)
    cell = np.arctan2(centre[:, 1], centre[:, 0])
    c, s = np.cos(cell), np.sin(cell)
    cells = {**cells, "stress": [np.column_stack([sxx, sxy, zero, sxy, syy, zero, zero, zero, szz])],
             "sigma_rr": [c * c * sxx + s * s * syy + 2 * c * s * sxy],
             "sigma_thth": [s * s * sxx + c * c * syy - 2 * c * s * sxy],
             "sigma_rth": [c * s * (syy - sxx) + (c * c - s * s) * sxy]}
    return time, points, cells


def write_xdmf(run: FemRun, path) -> Path:
    """Write the volume snapshots of ``run`` to ``path`` (``.xdmf``) and its ``.h5`` companion.

    See the module docstring for the fields, their units (lengths ``R``, stresses ``E``,
    times in seconds) and how the files are replaced. Returns ``path``.

    Parameters
    ----------
    run : FemRun
        From `integrate_fem` with ``volume_every`` (it has at least one volume snapshot).
    path : path-like
        A file name ending in ``.xdmf`` in an existing folder; the HDF5 data go to the same
        name ending in ``.h5``. Existing files are replaced.
    """
    if not isinstance(run, FemRun):
        raise ParameterError("run", type(run).__name__, "a FemRun (from integrate_fem)")
    if not run.settings.get("volume_every") or len(run.snapshots.get("vol_t", ())) == 0:
        raise ParameterError("run", "a run without volume snapshots", "a FemRun integrated with volume_every=T "
                             "(volume snapshots every T transits), holding at least one")
    scheme, snaps = run.scheme, run.snapshots
    body = scheme.problem.system.body
    points = np.column_stack([body.points, np.zeros(len(body.points))])
    physical = scheme.params.physical
    per_second = 1.0 if physical is None else physical.omega  # the paper's time is Omega t
    steps = ((time / per_second, points, cells) for time, points, cells in
             (_polar(scheme, snaps, k) for k in range(len(snaps["vol_t"]))))
    return write_xdmf_series(path, points, [(body.kind, body.cells.astype(np.int64))], steps)
