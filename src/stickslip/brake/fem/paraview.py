"""ParaView output of an FE run: the mesh and its volume snapshots as an XDMF time series.

`write_xdmf(run, path)` writes the volume snapshots that `integrate_fem(..., volume_every=T)`
keeps (see `FemRun`) with meshio's ``xdmf.TimeSeriesWriter``: ``path`` (``.xdmf``, XML) and
its HDF5 companion ``path.with_suffix(".h5")`` beside it, which ParaView opens (XDMF reader;
it shows meshio's layout as two blocks, the time series and the static ``mesh``) and
``meshio.xdmf.TimeSeriesReader`` reads back.

Units are the paper's: points and displacements in units of ``R`` (the bore radius), so the
mesh is the annulus ``1 <= r <= xi`` at ``z = 0``; velocities in ``R Omega``; stresses,
pressures and tractions in units of ``E``; times are the paper's ``t = Omega t̄`` (the
snapshot times ``vol_t`` of the run). XDMF has no place for units, hence this list. Vectors
are Cartesian and padded with ``z = 0`` (ParaView's 3-component vectors). Per snapshot:

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
    ``stress``: the Cartesian tensor, 9 components row by row (``xx xy xz yx yy yz zx zy zz``,
    ``sigma_zz = lambda (eps_xx + eps_yy)``); ``sigma_rr``, ``sigma_thth``, ``sigma_rth``:
    its polar components at the cell's centre angle.

The files are written in a hidden temporary folder beside ``path`` (removed afterwards, or
left behind by a killed process) and moved into place, the ``.h5`` first, then the
``.xdmf``: an interrupted write leaves no partial file under either name (only a kill between
the two moves would pair an older ``.xdmf`` with the new ``.h5``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ...errors import ParameterError
from ...fem import Material, assemble
from ...fem.assembly import cell_stress
from ...files import write_xdmf_series
from .mesh import FemSystem
from .run import FemRun

__all__ = ["write_xdmf"]


class _Fields:
    """Nodal Cartesian fields and cell stresses of one mesh, from free-dof vectors (polar frames)."""

    def __init__(self, system: FemSystem):
        mesh = system.mesh.mesh
        self.nodes, self.n_contact = mesh.p.shape[1], system.n_contact
        ang = np.arctan2(mesh.p[1], mesh.p[0])
        self.cos, self.sin = np.cos(ang), np.sin(ang)
        centre = mesh.p[:, mesh.t].mean(axis=1)
        cell = np.arctan2(centre[1], centre[0])
        self.cell_cos, self.cell_sin = np.cos(cell), np.sin(cell)
        self.general = assemble(system.mesh.body, Material(1.0, system.nu, 1.0, scaled=True))
        self.nu = system.nu

    def polar(self, free: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Free-dof vector -> ``(radial, hoop)`` at every node (0 on the clamped ring)."""
        full = np.zeros(2 * self.nodes)
        full[:free.size] = free
        return full[0::2], full[1::2]

    def cartesian(self, radial, hoop) -> np.ndarray:
        """Polar components at the nodes -> ``(nodes, 3)`` Cartesian vectors, ``z = 0``."""
        return np.column_stack([self.cos * radial - self.sin * hoop, self.sin * radial + self.cos * hoop,
                                np.zeros(self.nodes)])

    def stress(self, ux, uy) -> tuple[np.ndarray, tuple]:
        """Cell means of the plane-strain stress: the 9-component tensor and ``(rr, thth, rth)``."""
        u = np.empty(2 * self.nodes)
        u[0::2], u[1::2] = ux, uy
        sxx, syy, sxy = cell_stress(self.general, u).T
        szz = self.nu * (sxx + syy)  # plane strain: lambda (eps_xx + eps_yy)
        zero = np.zeros_like(sxx)
        tensor = np.column_stack([sxx, sxy, zero, sxy, syy, zero, zero, zero, szz])
        c, s = self.cell_cos, self.cell_sin
        polar = (c * c * sxx + s * s * syy + 2 * c * s * sxy, s * s * sxx + c * c * syy - 2 * c * s * sxy,
                 c * s * (syy - sxx) + (c * c - s * s) * sxy)
        return tensor, polar

    def snapshot(self, u, v, P, Q, state) -> tuple[dict, dict]:
        """Point and cell data of one volume snapshot."""
        ur, ut = self.polar(u)
        disp = self.cartesian(ur, ut)
        on = slice(0, self.n_contact)  # the contact nodes come first (r = 1)
        p, q, code = np.zeros(self.nodes), np.zeros(self.nodes), np.full(self.nodes, -1, dtype=np.int32)
        p[on], q[on], code[on] = P, Q, state
        tensor, (srr, stt, srt) = self.stress(disp[:, 0], disp[:, 1])
        points = {"displacement": disp, "u_r": ur, "u_theta": ut, "velocity": self.cartesian(*self.polar(v)),
                  "contact_pressure": p, "contact_shear": q, "contact_traction": self.cartesian(p, q),
                  "contact_state": code}
        cells = {"stress": [tensor], "sigma_rr": [srr], "sigma_thth": [stt], "sigma_rth": [srt]}
        return points, cells


def write_xdmf(run: FemRun, path) -> Path:
    """Write the volume snapshots of ``run`` to ``path`` (``.xdmf``) and its ``.h5`` companion.

    See the module docstring for the fields, their units (lengths ``R``, stresses ``E``,
    times ``Omega t``) and how the files are replaced. Returns ``path``.

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
    fields, mesh = _Fields(run.scheme.system), run.scheme.system.mesh.mesh
    points = np.column_stack([mesh.p.T, np.zeros(mesh.p.shape[1])])
    snaps = run.snapshots
    steps = ((t, *fields.snapshot(*(snaps[f"vol_{n}"][k] for n in ("u", "v", "P", "Q", "state"))))
             for k, t in enumerate(snaps["vol_t"]))
    return write_xdmf_series(path, points, [("quad", mesh.t.T.astype(np.int64))], steps)
