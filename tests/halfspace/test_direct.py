"""Direct problem: (c, b) from the loading (T, v, v*)."""

import numpy as np
import pytest

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.halfspace import direct_map, direct_problem, inverse_problem, radok
from stickslip.halfspace.direct import cbar_grid

NU, MU, VS = 0.3, 0.5, 1e-3


@pytest.mark.parametrize("system", ["printed", "text"])
def test_round_trip_inverse_then_direct(system):
    rng = np.random.default_rng(4)
    for _ in range(12):
        b = 1 + 10 ** rng.uniform(-1.5, 2)
        c = -rng.uniform(0.02, 0.98)
        if system == "text":  # stay on the admissible side of D = 0
            rd = radok(c, NU, MU)
            b = max(b, 1.2 * float(rd.K / (2 * rd.K_minus_one)))
        inv = inverse_problem(b, c, VS, nu=NU, mu=MU, system=system)
        sol = direct_problem(float(inv.T), float(inv.v), VS, nu=NU, mu=MU, system=system)
        found = [s for s in sol.solutions if abs(s[0] - c) < 1e-9]
        assert found, (b, c, sol.solutions)
        assert found[0][1] == pytest.approx(b, rel=1e-8)
        assert max(abs(r) for r in sol.residuals) < 1e-10


def test_printed_solution_is_unique_because_K_is_monotone():
    for nu in (0.0, 0.3, 0.49):
        for mu in (0.05, 0.5, 5.0):
            K = radok(cbar_grid(20001), nu, mu).K   # grid runs from c = 0- to c = -1+
            assert np.all(np.diff(K) <= 1e-15) and K[0] > K[-1]


def test_figure14_loading_is_solved_uniquely():
    inv = inverse_problem(11.358175100459, -0.7, VS, nu=NU, mu=MU)
    sol = direct_problem(float(inv.T), float(inv.v), VS, nu=NU, mu=MU)
    assert sol.unique and sol.c == pytest.approx(-0.7, abs=1e-12) and sol.b == pytest.approx(11.358175100459, rel=1e-10)
    assert sol.mu_star[0] == pytest.approx(MU + float(inv.T) * -0.7 * NU / (2 * VS), rel=1e-12)
    d = sol.to_dict()
    assert set(d) >= {"c", "b", "unique", "solutions"}


def test_no_solution_outside_the_speed_band():
    K = radok(cbar_grid(20001), NU, MU).K
    band = (K / (K - 1)).min(), (K / (K - 1)).max()
    with pytest.raises(NoSolutionError, match="no stick-slip wave"):
        direct_problem(0.01, 0.99 * band[0] * VS, VS, nu=NU, mu=MU)
    with pytest.raises(NoSolutionError, match="no stick-slip wave"):
        direct_problem(0.01, 1.01 * band[1] * VS, VS, nu=NU, mu=MU)
    with pytest.raises(NoSolutionError, match="v > v_star"):
        direct_problem(0.01, 0.5 * VS, VS, nu=NU, mu=MU)
    direct_problem(0.01, 0.5 * (band[0] + band[1]) * VS, VS, nu=NU, mu=MU)  # inside: found


def test_v_star_zero_has_no_wave():
    with pytest.raises(NoSolutionError, match="trivial"):
        direct_problem(0.01, 0.004, 0.0, nu=NU, mu=MU)


@pytest.mark.parametrize("kwargs, name", [
    (dict(T=0.0, v=0.004, v_star=VS), "T"), (dict(T=-1.0, v=0.004, v_star=VS), "T"),
    (dict(T=0.01, v=0.0, v_star=VS), "v"), (dict(T=0.01, v=0.004, v_star=-VS), "v_star"),
    (dict(T=float("nan"), v=0.004, v_star=VS), "T"),
    (dict(T=0.01, v=0.004, v_star=1e308), "v_star"),  # (1e308 made NaN fields: v* is at most 1)
])
def test_direct_rejects_bad_input(kwargs, name):
    with pytest.raises(ParameterError) as err:
        direct_problem(**kwargs, nu=NU, mu=MU)
    assert err.value.name == name


@pytest.mark.parametrize("system", ["printed", "text"])
def test_map_agrees_with_direct_problem(system):
    vr = np.geomspace(1.5, 20, 9)
    tr = np.geomspace(0.05, 50, 7)
    ds = direct_map(vr, tr, nu=NU, mu=MU, system=system)
    assert ds.n_solutions.max() <= 1
    for i, v in enumerate(vr):
        for j, t in enumerate(tr):
            n = int(ds.n_solutions[i, j])
            try:
                sol = direct_problem(t * VS, v * VS, VS, nu=NU, mu=MU, system=system)
            except NoSolutionError:
                assert n == 0
                continue
            assert n == len(sol.solutions)
            assert float(ds.c[i, j, 0]) == pytest.approx(sol.c, abs=1e-10)
            assert float(ds.b[i, j, 0]) == pytest.approx(sol.b, rel=1e-8)
    assert int((ds.n_solutions > 0).sum()) > 0
