"""CEA sweeps with tracked modes (issue 24): the critical value located by the sweep against
the 1-DOF oscillator's closed form, tracking by shape through a frequency crossing (where
sorting by frequency swaps the modes), and the command line's refusals."""

import json
import math
import shutil
import subprocess
import sys

import numpy as np
import pytest

from stickslip.cli import run
from stickslip.fem.tracking import cea_sweep, track

from .test_examples import EXAMPLES

N, M, FS, FD, VS, V = 1.0e5, 1.0, 0.6, 0.4, 0.2, 1.0


@pytest.fixture(scope="module")
def stiff_block(tmp_path_factory):
    """The block example made stiff (E = 1e12 Pa), on a Stribeck law, damped by alpha."""
    folder = tmp_path_factory.mktemp("block")
    subprocess.run([sys.executable, str(EXAMPLES / "block_on_belt" / "mesh.py"), "block.msh"], cwd=folder, check=True)
    text = (EXAMPLES / "block_on_belt" / "block.toml").read_text()
    text = text.replace("young = 1.0e9", "young = 1.0e12").replace("density = 1000.0", "density = 1000.0\nalpha = 100.0")
    text = text.replace("static_friction = 0.6", f'static_friction = {FS}\nlaw = "stribeck"\nstribeck_speed = {VS}')
    text = text.replace("band = [0.0, 40000.0]", "band = [0.0, 400.0]").replace("count = 30", "count = 10")
    (folder / "stiff.toml").write_text(text)
    return folder / "stiff.toml"


def test_the_sweep_locates_the_critical_damping_of_the_oscillators_closed_form(stiff_block, tmp_path):
    """m x'' + (alpha m + N mu'(V)) x' + k x = 0 turns stable at alpha* = N (f_s - f_d) e^(-V/v_s) / (v_s m)
    = 673.79 1/s. Swept over 0-1000 in 6 points (step 200), the bisection brackets it to 1 % of
    the step: within 2 1/s."""
    exact = N * (FS - FD) * math.exp(-V / VS) / (VS * M)
    tracked = cea_sweep(stiff_block, "alpha", np.linspace(0.0, 1000.0, 6), tmp_path / "s.zarr", workers=1)
    assert tracked.key == "material.alpha" and len(tracked.s) == 1
    assert abs(tracked.critical[0] - exact) <= 2.0 and tracked.turn[0] == -1
    again = cea_sweep(stiff_block, "alpha", np.linspace(0.0, 1000.0, 6), tmp_path / "s.zarr", workers=1)
    assert np.array_equal(again.s, tracked.s)  # resumed from the store: nothing recomputed differs


@pytest.mark.slow
def test_the_bisections_on_two_workers_find_what_one_finds(stiff_block, tmp_path):
    """The rounds of bisection run in parallel on a process pool: the same decisions, so the same
    critical value; the frequency there to the eigensolver's tolerance (another process's ARPACK
    run differs by some 1e-10). By multisection (the default: two values a round in the one
    bracket) the bracket differs but holds the same crossing: within the tolerance (1 % of the
    step, 2)."""
    one = cea_sweep(stiff_block, "alpha", np.linspace(0.0, 1000.0, 6), tmp_path / "a.zarr", workers=1)
    two = cea_sweep(stiff_block, "alpha", np.linspace(0.0, 1000.0, 6), tmp_path / "b.zarr", workers=2,
                    multisection=False)
    assert np.array_equal(one.critical, two.critical, equal_nan=True)
    assert np.allclose(one.critical_frequency, two.critical_frequency, rtol=1e-8, equal_nan=True)
    multi = cea_sweep(stiff_block, "alpha", np.linspace(0.0, 1000.0, 6), tmp_path / "c.zarr", workers=2)
    assert np.all(np.abs(multi.critical - one.critical) <= 2.0)


def test_tracking_by_shape_follows_two_modes_through_a_frequency_crossing():
    """Two modes of fixed, different shapes whose frequencies cross between points 4 and 5:
    each branch keeps its shape (and its frequency trend); sorting by frequency would swap them
    at the crossing."""
    rng = np.random.default_rng(1)
    a, b = rng.standard_normal(64) + 0j, rng.standard_normal(64) + 0j
    s_points, sketches = [], []
    for p in range(10):
        fa, fb = 100.0 + 10 * p, 145.0 - 5 * p  # cross between p = 3 and p = 4
        order = np.argsort([fa, fb])  # the modes come sorted by frequency, as a CEA lists them
        s = np.array([1j * fa, 1j * fb])[order]
        x = np.array([a, b])[order]
        s_points.append(s)
        sketches.append(x + 0.05 * rng.standard_normal(x.shape))
    branches, _ = track(s_points, sketches)
    assert len(branches) == 2
    slopes = sorted(float(np.mean(np.diff(br.imag))) for br in branches)
    assert slopes == pytest.approx([-5.0, 10.0])


def test_tracking_follows_the_complex_whirl_modes_of_two_turning_rotors():
    """Issue 44: flutter modes are complex, and the tracker must compare them as such. Two
    isotropic rotors, uncoupled (dofs 0-1 and 2-3), seen in a frame turning at Omega:
    ``q'' + 2 Omega J q' + (w_i^2 - Omega^2) q = 0``, ``J = [[0, -1], [1, 0]]``. Each has a
    whirl of each sense: circular complex shapes ``(1, +-i)`` of frequencies ``w_i +- Omega``
    (substitute ``(1, sigma i) e^(i w t)``: ``(w - sigma Omega)^2 = w_i^2``), orthogonal in the
    Hermitian product but not in the plain one (where each has zero length). With w = 10, 14 and
    Omega swept over 0.3-5.3, rotor A's ``(1, i)`` whirl crosses rotor B's ``(1, -i)`` whirl
    (at Omega = 2); each point's modes come sorted by frequency
    (as a CEA lists them), from a dense eigensolver (scipy), each scaled by a random complex
    factor. Each branch must keep its rotor and its whirl at every point; a tracker that uses
    the plain product (no conjugate), the real part only or no modulus links whirls of opposite
    senses or loses links."""
    import scipy.linalg as sla

    rng = np.random.default_rng(44)
    J = np.array([[0.0, -1.0], [1.0, 0.0]])
    omegas = np.linspace(0.3, 5.3, 11)  # not 2.0: no point at the double eigenvalue
    s_points, sketches, labels = [], [], []
    for omega in omegas:
        C = np.zeros((4, 4))
        C[:2, :2] = C[2:, 2:] = 2 * omega * J
        K = np.diag([10.0**2, 10.0**2, 14.0**2, 14.0**2]) - omega**2 * np.eye(4)
        A = np.block([[np.zeros((4, 4)), np.eye(4)], [-K, -C]])
        s, V = sla.eig(A)
        keep = np.flatnonzero(s.imag > 0)
        keep = keep[np.argsort(s[keep].imag)]
        shapes = V[:4, keep].T * (rng.uniform(0.5, 2.0, keep.size) * np.exp(2j * np.pi * rng.random(keep.size)))[:, None]
        # the label of each mode by construction: its rotor, and its whirl's sense (y/x = +-i)
        rotor = (np.abs(shapes[:, 2]) > np.abs(shapes[:, 0])).astype(int)
        ratio = np.array([x[2 * r + 1] / x[2 * r] for x, r in zip(shapes, rotor)])
        assert np.allclose(np.abs(ratio), 1.0) and np.allclose(np.abs(ratio.real), 0.0, atol=1e-9)
        labels.append([(int(r), int(np.sign(q.imag))) for r, q in zip(rotor, ratio)])
        s_points.append(s[keep])
        sketches.append(shapes)
    expected = {(0, 1): 10.0 + omegas, (0, -1): 10.0 - omegas, (1, 1): 14.0 + omegas, (1, -1): 14.0 - omegas}
    for p, omega in enumerate(omegas):  # the frequencies the labels say
        for k, label in enumerate(labels[p]):
            assert s_points[p][k].imag == pytest.approx(expected[label][p], rel=1e-9)
    crossing = [labels[p].index((0, 1)) < labels[p].index((1, -1)) for p in range(len(omegas))]
    assert crossing[0] and not crossing[-1]  # the frequency order of two modes does change
    branches, where = track(s_points, sketches)
    assert branches.shape == (4, len(omegas)) and np.all(where >= 0)
    for b in range(4):
        assert len({labels[p][where[b, p]] for p in range(len(omegas))}) == 1, (b, where[b])


def test_a_branch_that_starts_later_has_no_frequency_before_it_not_zero():
    """Issue 44: a branch born at the third value stored frequency 0 Hz at the first two (a false
    line at 0 Hz in the sweep's plot); where it has no mode, its growth rate and frequency are NaN."""
    from stickslip.fem.tracking import Tracked

    rng = np.random.default_rng(2)
    a, b = rng.standard_normal(32) + 0j, rng.standard_normal(32) + 0j
    s_points = [np.array([-1 + 100j]), np.array([-1 + 101j]), np.array([-1 + 102j, 2 + 300j])]
    sketches = [np.array([a]), np.array([a]), np.array([a, b])]
    s, where = track(s_points, sketches)
    assert s.shape == (2, 3) and list(where[1]) == [-1, -1, 1]
    ds = Tracked("contact.friction", np.array([0.1, 0.2, 0.3]), s, np.full(2, np.nan), np.full(2, np.nan),
                 np.full(2, -1), np.zeros(2, int), 1e-2, (0.0, 1e3)).to_xarray()
    freq = ds["frequency"].values
    assert np.isnan(freq[1, :2]).all() and freq[1, 2] == pytest.approx(300 / (2 * math.pi))
    assert np.isnan(ds["growth_rate"].values[1, :2]).all() and "NaN" in ds["frequency"].attrs["comment"]


@pytest.mark.parametrize("args, words", [
    (["--sweep", "colour=0:1:3", "--store", "s.zarr"], ["--sweep = 'colour'", "contact.friction"]),
    (["--sweep", "friction=0:20:3", "--store", "s.zarr"], ["--sweep = 'friction=0:20:3'", "at 10", "contact.static_friction = 0.6 must be >="]),
    (["--sweep", "friction=0:0.5:3"], ["missing --store"]),
    (["--sweep", "friction=0:0.5:3", "--store", "s.zarr", "--xdmf", "m.xdmf"], ["--xdmf"]),
    (["--store", "s.zarr"], ["--store", "left out without --sweep"]),
])
def test_a_sweep_asked_wrong_is_one_line_naming_the_option(stiff_block, tmp_path, args, words, capsys):
    args = [str(tmp_path / a) if a.endswith((".zarr", ".xdmf")) else a for a in args]
    assert run(["fem", "cea", str(stiff_block), *args]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1, err
    for w in words:
        assert w in err, err
    assert not (tmp_path / "s.zarr").exists()


def test_the_command_writes_the_tracked_branches_and_the_map(stiff_block, tmp_path, capsys):
    from stickslip.cf import load_result

    from ..cf_rules import problems

    args = ["fem", "cea", str(stiff_block), "--sweep", "alpha=0:1000:3", "--store", str(tmp_path / "s.zarr"),
            "--out", str(tmp_path / "t.nc"), "--plot", str(tmp_path / "t.png"), "--workers", "1", "--json"]
    assert run(args) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["swept_key"] == "material.alpha" and data["branches"] == 1 and len(data["critical"]) == 1
    ds = load_result(tmp_path / "t.nc")
    assert problems(ds, "tracked") == [] and ds.sizes["value"] == 3
    assert (tmp_path / "t.png").stat().st_size > 1000
    shutil.rmtree(tmp_path / "s.zarr")
