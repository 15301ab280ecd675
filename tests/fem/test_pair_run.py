"""Explicit runs of two deformable bodies in contact (issue 24): a pad (clamped at its back,
pressed 2 micrometres in, f = 0.5) on a block sliding under it.

* Steady sliding of the pair (`steady_pair`, a linear solve) is a state of the scheme: left
  unperturbed, 2000 steps keep it to 1e-12 of its largest displacement (with a law of the slip
  speed and a coefficient of the pressure too, to 1e-10: each node's coefficient found by
  fixed-point iteration in steady sliding and at its own force in the coupled kernel).
* The energy books of `stickslip.contact.energy` close to round-off (1e-10 of the largest
  change of energy per step) at beta2 = 1/2 and 0.9, on a start violent enough that nodes
  stick, slip and separate. Their contact terms are computed from each slave node's force on
  the *relative* motion of the bodies, so a force that does not act equal and opposite on
  the master (planted: 0.9 of it) leaves a residual.
* A partner stiffer and heavier by the same factor (its frequencies unchanged: the same step)
  reproduces the run of the pad on a rigid flat (the verified single-body scheme): the contact
  nodes' displacements over 2000 steps within 10 x the compliance ratio, first order in it
  (the error at 1e2 at least 5 times that at 1e3), every node state the same; with a Stribeck
  law and a coefficient of the pressure too (the two kernels scale the pressure their own way:
  the rigid one from a reaction per unit mass and the tributary length, the coupled one from a
  force and the mortar's weight).
* The explicit run and the CEA, two independent routes to the same linear dynamics: from
  steady sliding perturbed by 1e-9, the energy of the run grows (while every node slips) at
  twice the discrete growth rate (`discrete_rates`, central differences) of the CEA's most
  unstable eigenvalue, to 1e-3; and converges to the CEA's own rate at second order in dt.
* The command line: `fem run` on a config with a [partner] writes its run and both bodies'
  ParaView snapshots; what it cannot do is refused in one line.
"""

import numpy as np
import pytest

from stickslip.cli import run
from stickslip.contact.energy import energy_books, trace
from stickslip.contact.states import SLIP_POS
from stickslip.fem import ContactProblem, Material, RigidFlat, assemble, body_from_meshio, contact_frames
from stickslip.fem.pair import PairProblem, Translation
from stickslip.fem.pair_run import PairRun, PairScheme, integrate_pair
from stickslip.fem.run import perturbed_steady_body
from stickslip.fem.scheme import BodyScheme
from stickslip.friction import LinearWeakening, PressurePower, Stribeck

from .meshes import rectangle


def _shifted(path, dx, dy, **options):
    return body_from_meshio(rectangle(path, origin=(dx, dy), **options), path.name)


@pytest.fixture(scope="module")
def bodies(tmp_path_factory):
    folder = tmp_path_factory.mktemp("pair_run")
    pad = _shifted(folder / "pad.msh", 0.0, 0.0, width=0.04, height=0.01, size=0.004)
    under = _shifted(folder / "under.msh", -0.005, -0.01 + 2e-6, width=0.05, height=0.01, size=0.003)
    return folder, assemble(pad, Material(1e8, 0.25, 25.0)), under


def _pair(bodies, ratio=1.0, friction=0.5, **laws):
    _, system, under = bodies
    partner = assemble(under, Material(1e8 * ratio, 0.25, 25.0 * ratio))
    friction = {"law": laws.pop("law")} if "law" in laws else {"friction": friction}
    return PairProblem(system, "bottom", partner, "top", Translation((1.0, 0.0)), clamped_slave=("top",),
                       clamped_master=("bottom",), **friction, **laws)


#: a law of the slip speed and a coefficient that falls with the pressure (about 2e4 Pa under the pad)
LAWS = {"law": Stribeck(0.6, 0.5, 0.2), "pressure_law": PressurePower(2e4, 0.3)}


@pytest.mark.parametrize("laws, tol", [({}, 1e-12), ({"law": LinearWeakening(0.5, 0.5, 0.1),
                                                       "pressure_law": PressurePower(2e4, 0.3)}, 1e-10)],
                         ids=["coulomb", "weakening-and-pressure"])
def test_steady_sliding_of_the_pair_is_a_state_of_the_scheme(bodies, laws, tol):
    scheme = PairScheme(_pair(bodies, **laws))
    u_e, r_n, r_t = scheme.steady_reference()
    assert (r_n > 0).sum() >= 5
    state = scheme.initial_state(u_e, np.zeros_like(u_e))
    out = scheme.advance(state, 2000)
    assert np.abs(state.u - u_e).max() <= tol * np.abs(u_e).max()
    assert np.abs(out.lam_t - r_t).max() <= 1e3 * tol * np.abs(r_t).max()


@pytest.mark.parametrize("beta2", [0.5, 0.9])
def test_the_energy_books_of_two_bodies_close(bodies, beta2):
    scheme = PairScheme(_pair(bodies), beta2=beta2)
    start = perturbed_steady_body(scheme, 30.0, 1)
    tr = trace(scheme, scheme.initial_state(start.u, start.v), 400)
    books = energy_books(tr)
    seen = np.bincount(tr.state.ravel(), minlength=4)
    assert (seen > 0).all(), seen  # stick, slip, reverse slip and separation all occur
    assert np.abs(books.residual).max() <= 1e-10 * np.abs(np.diff(books.energy)).max()
    assert books.surface_work.sum() > 0 and books.friction_dissipation.sum() > 0


@pytest.mark.parametrize("laws", [{}, LAWS], ids=["coulomb", "stribeck-and-pressure"])
def test_a_stiff_heavy_partner_reproduces_the_pad_on_a_rigid_flat(bodies, laws):
    _, system, _ = bodies
    frames = contact_frames(system.body, "bottom", RigidFlat((0, 2e-6), (0, 1), (1.0, 0)))
    rigid = ContactProblem(system, frames, clamped=("top",), **(laws or {"friction": 0.5}))
    errors = []
    for ratio in (1e2, 1e3):
        pair = PairScheme(_pair(bodies, ratio, **laws))
        dt = min(pair.dt, BodyScheme(rigid).dt)
        runs = []
        for scheme in (BodyScheme(rigid, time_step=dt), PairScheme(pair.params, time_step=dt)):
            start = perturbed_steady_body(scheme, 3.0, 2)
            state, out = scheme.initial_state(start.u, start.v), scheme.new_output()
            normal, tangent = scheme.contact_dofs
            rows = []
            for _ in range(100):
                scheme.advance(state, 20, True, out)
                rows.append((np.concatenate([state.u[normal], state.u[tangent]]), out.state.copy()))
            runs.append(rows)
        (a, b) = ([np.array([r[0] for r in rows]) for rows in runs])
        states = [np.array([r[1] for r in rows]) for rows in runs]
        assert np.array_equal(*states) and (states[0] != 1).any()
        errors.append(np.abs(a - b).max() / np.abs(a).max())
    assert errors[1] <= 10 / 1e3 and errors[0] >= 5 * errors[1], errors


def linear_growth(scheme):
    """The growth rate of a run from steady sliding perturbed by 1e-9, fitted to the energy's
    second half while every contact node slips (the linear regime)."""
    start = perturbed_steady_body(scheme, 1e-9, 0)
    state, out = scheme.initial_state(start.u, start.v), scheme.new_output()
    ref, chunk, energy = scheme.steady_reference()[0], max(1, int(2e-6 / scheme.dt)), []
    while len(energy) < 5000:
        scheme.advance(state, chunk, True, out)
        energy.append(sum(scheme.energies(out.u_prev, state.u, ref)))
        if (out.state != SLIP_POS).any():
            break
    t = chunk * scheme.dt * np.arange(1, len(energy) + 1)
    keep = slice(len(energy) // 2, len(energy) - 2)
    assert len(energy) > 200  # a long linear regime to fit
    return np.polyfit(t[keep], np.log(energy[keep]), 1)[0] / 2


def test_a_run_grows_at_the_rate_of_the_ceas_most_unstable_mode(bodies):
    from stickslip.contact.scheme import discrete_rates
    from stickslip.fem.cea import complex_eigenvalues

    problem = _pair(bodies)
    modes = complex_eigenvalues(problem, (0.0, 3e5), count=40)
    s = modes.s[np.argmax(modes.growth_rate)]
    assert s.real > 1e3
    scheme = PairScheme(problem, beta2=0.5)
    expected = discrete_rates(np.array([-s**2]), scheme.dt, 0.5)[0].real
    assert linear_growth(scheme) == pytest.approx(expected, rel=1e-3)


@pytest.mark.slow
def test_the_runs_growth_converges_to_the_ceas_at_second_order(bodies):
    from stickslip.fem.cea import complex_eigenvalues

    problem = _pair(bodies)
    modes = complex_eigenvalues(problem, (0.0, 3e5), count=40)
    exact = modes.growth_rate.max()
    errors = [abs(linear_growth(PairScheme(problem, beta2=0.5, courant=c)) / exact - 1) for c in (0.9, 0.3)]
    assert 9 * 0.7 <= errors[0] / errors[1], errors  # dt / 3: at least 0.7 of second order's 9


CONFIG = """mesh = "pad.msh"
clamped = ["top"]
[material]
young = 1.0e8
poisson = 0.25
density = 25.0
[contact]
group = "bottom"
friction = 0.5
[partner]
mesh = "under.msh"
group = "top"
clamped = ["bottom"]
velocity = [1.0, 0.0]
[partner.material]
young = 2.0e8
poisson = 0.3
density = 50.0
"""


def test_fem_run_takes_a_partner(bodies, capsys):
    import meshio
    import xarray as xr

    folder = bodies[0]
    config = folder / "pair.toml"
    config.write_text(CONFIG)
    out, xdmf = folder / "run.nc", folder / "run.xdmf"
    assert run(["fem", "run", str(config), "--transits", "2", "--out", str(out), "--xdmf", str(xdmf),
                "--xdmf-every", "1", "--json"]) == 0
    capsys.readouterr()
    with xr.open_dataset(out) as ds:
        assert ds.attrs["master_mesh"] == "under.msh" and np.isfinite(ds["P"].values).all()
        assert (ds["P"].values > 0).any()
    with meshio.xdmf.TimeSeriesReader(xdmf) as reader:
        points, cells = reader.read_points_cells()
        _, point_data, cell_data = reader.read_data(reader.num_steps - 1)
    assert len(points) == sum(len(b.points) for b in (bodies[1].body, bodies[2]))
    assert set(np.unique(point_data["body"])) == {0, 1}
    cells_of_both = sum(len(b.cells) for b in (bodies[1].body, bodies[2]))
    assert sum(len(v) for v in cell_data["von_mises"]) == cells_of_both


@pytest.mark.parametrize("extra, words", [
    (["--start", "rest"], "--start"),
    (["--time-step", "1.0"], "--time-step"),
    (["--alpha"], "material.alpha"),  # the partner damped, the pad not: one (alpha, beta) per explicit run
])
def test_fem_run_of_a_pair_refuses_in_one_line(bodies, capsys, extra, words):
    folder = bodies[0]
    config = folder / "bad_pair.toml"
    damped = extra == ["--alpha"]
    config.write_text(CONFIG.replace("density = 50.0", "density = 50.0\nalpha = 5.0") if damped else CONFIG)
    assert run(["fem", "run", str(config), "--transits", "1", *([] if damped else extra)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err, err


def test_a_checkpoint_of_another_pair_is_refused(bodies, tmp_path):
    from stickslip.errors import ParameterError

    path = tmp_path / "run.nc"
    first = integrate_pair(_pair(bodies), transits=0.5, checkpoint=path)
    assert isinstance(first, PairRun) and first.complete
    with pytest.raises(ParameterError):
        integrate_pair(_pair(bodies, friction=0.4), transits=0.5, checkpoint=path)


@pytest.mark.parametrize("rollers", [{"rollers_slave": {"left": "x"}}, {"rollers_slave": {"left": "y"}},
                                     {"rollers_master": {"top": "y"}}])
def test_contact_nodes_held_along_one_axis_only_are_refused(bodies, rollers):
    """A roller through the contact line holds a contact node along one axis: until now the scheme
    dropped the node's contact (x held) or wrote its force into another dof (y held)."""
    from stickslip.errors import ParameterError

    _, system, under = bodies
    problem = PairProblem(system, "bottom", assemble(under, Material(1e8, 0.25, 25.0)), "top", Translation((1.0, 0.0)),
                          friction=0.5, clamped_slave=("top",), clamped_master=("bottom",), **rollers)
    with pytest.raises(ParameterError, match="along some axes only"):
        PairScheme(problem)
