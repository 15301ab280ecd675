"""ParaView output of a general body, read back with meshio: the run's snapshots hold the
steady contact (bore pushed out by the interference, rim clamped, contact forces summing to
the steady normal force) and the mode file holds the CEA shapes, each solving its eigenproblem."""

import meshio
import numpy as np
import pytest

from stickslip.brake.fem import FemScheme
from stickslip.errors import ParameterError
from stickslip.fem.assembly import cell_stress
from stickslip.fem.cea import complex_eigenvalues, linearised
from stickslip.fem.paraview import write_modes_xdmf, write_run_xdmf
from stickslip.fem.run import integrate_body, perturbed_steady_body
from stickslip.fem.scheme import BodyScheme

from .test_scheme import PARAMS, general_annulus


@pytest.fixture(scope="module")
def annulus():
    return general_annulus(FemScheme(PARAMS, 32, 2, 0.9)).params


def test_run_snapshots_read_back_with_the_steady_contact(annulus, tmp_path):
    run = integrate_body(annulus, transits=3.0, volume_every=1.0, initial=None)
    path = write_run_xdmf(run, tmp_path / "run.xdmf")
    body, frames = annulus.system.body, annulus.frames
    with meshio.xdmf.TimeSeriesReader(path) as reader:
        points, cells = reader.read_points_cells()
        assert points.shape == (len(body.points), 3) and cells[0].data.shape == body.cells.shape
        assert reader.num_steps == len(run.snapshots["vol_t"]) >= 4
        t0, start, _ = reader.read_data(0)  # the start: the perturbed steady state the run began from
        t, data, cell_data = reader.read_data(1)  # a transit later
    initial = perturbed_steady_body(BodyScheme(annulus))
    assert t0 == 0.0 < t and np.array_equal(start["displacement"][:, :2].ravel(), BodyScheme(annulus).cartesian(initial.u))
    u = data["displacement"][:, :2]
    sigma = cell_stress(annulus.system, u.ravel())  # the cell stresses are those of the displacement written
    for k, name in enumerate(("stress_xx", "stress_yy", "stress_xy")):
        assert np.allclose(cell_data[name][0], sigma[:, k], rtol=1e-12, atol=1e-12 * np.abs(sigma).max())
    assert np.all(cell_data["von_mises"][0] >= np.abs(sigma[:, 2]) * np.sqrt(3) * (1 - 1e-12))
    bore = frames.nodes
    assert np.allclose(np.sum(u[bore] * frames.normal, axis=1), -frames.gap, rtol=2e-3)  # the interference
    assert np.all(u[body.nodes("rim")] == 0)
    steady = annulus.steady.pressure.sum()
    assert data["contact_pressure"].sum() == pytest.approx(steady, rel=2e-2)
    assert set(np.unique(data["contact_state"])) <= {-1, 0, 1, 2, 3} and np.sum(data["contact_state"] >= 0) == len(bore)


def test_mode_shapes_read_back_and_solve_their_eigenproblem(annulus, tmp_path):
    modes = complex_eigenvalues(annulus, (0.0, 800.0), count=10, mode_shapes=True)
    path = write_modes_xdmf(annulus, modes, tmp_path / "modes.xdmf")
    K, _, m, kept = linearised(annulus)
    scheme = BodyScheme(annulus)
    with meshio.xdmf.TimeSeriesReader(path) as reader:
        reader.read_points_cells()
        assert reader.num_steps == len(modes.s)
        for k in range(reader.num_steps):
            _, data, _ = reader.read_data(k)
            u = (data["mode_real"][:, :2] + 1j * data["mode_imag"][:, :2]).ravel()
            w = (scheme.rotation.T @ u)[scheme.free][kept]  # back to the analysis' dofs
            s = modes.s[k]
            assert np.linalg.norm(s**2 * m * w + K @ w) <= 1e-7 * abs(s) ** 2 * np.linalg.norm(m * w)
            assert data["growth_rate"][0] == modes.growth_rate[k] and np.abs(u).max() == pytest.approx(1.0)


def test_a_run_without_volume_snapshots_is_refused(annulus, tmp_path):
    with pytest.raises(ParameterError) as err:
        write_run_xdmf(integrate_body(annulus, transits=1.0), tmp_path / "x.xdmf")
    assert err.value.name == "run"
