"""Systems with rate-and-state contacts (`stickslip.system.rate_state`): the stability of steady
sliding against the closed-form critical stiffness and Hopf frequency of the spring-slider (Ruina
1983, Rice & Ruina 1983), motions against solve_ivp of equations written out here."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb
from stickslip.rsf import RateState
from stickslip.system import (Contact, System, rate_state_simulate, rate_state_steady, simulate, steady_sliding,
                              system_from_dict)

N, V, M = 10.0, 1e-6, 1.0
A, B, DC, F0, V0 = 0.01, 0.015, 1e-5, 0.6, 1e-6


def _block(k, law, mass=M, damping=None):
    return System(mass=[[mass]], stiffness=[[k]], damping=damping,
                  contacts=[Contact([1.0], N, law, surface_speed=V)])


def _kc(mass=M):
    return N * (B - A) / DC * (1 + mass * V**2 / (N * A * DC))


@pytest.mark.parametrize("evolution", ["aging", "slip"])
@pytest.mark.parametrize("mass", [M, 1e-3, 50.0])
def test_steady_sliding_loses_stability_at_the_closed_form_critical_stiffness(evolution, mass):
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0, evolution=evolution)
    growth = lambda k: rate_state_steady(_block(k, law, mass)).growth_rate  # noqa: E731
    kc = _kc(mass)
    found = brentq(growth, 0.5 * kc, 2.0 * kc, xtol=1e-12 * kc, rtol=1e-14)
    assert found == pytest.approx(kc, rel=1e-8)
    at = rate_state_steady(_block(kc, law, mass)).eigenvalues[0]
    assert abs(at.imag) == pytest.approx(V / DC * math.sqrt((B - A) / A), rel=1e-6)  # the Hopf frequency
    assert not rate_state_steady(_block(0.99 * kc, law, mass)).stable
    assert rate_state_steady(_block(1.01 * kc, law, mass)).stable


def test_slow_steady_sliding_is_decided_by_its_slow_pair_not_called_marginal():
    """At V = 1e-9 m/s the direct effect's eigenvalue, -N a / (m V) = -1e11 1/s, dwarfs the slow pair
    (real part 2.5e-5 1/s): stable at twice k_c, unstable at half of it."""
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=1e-9)
    kc = 1e4 * (B - A) / DC * (1 + 1e-18 / (1e4 * A * DC))
    for k, stable in ((2 * kc, True), (0.5 * kc, False)):
        st = rate_state_steady(System(mass=[[1.0]], stiffness=[[k]],
                                      contacts=[Contact([1.0], 1e4, law, surface_speed=1e-9)]))
        assert st.stable == stable and not st.marginal and abs(st.growth_rate) > 1e-5


def test_steady_position_and_friction_are_those_of_steady_sliding():
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    k = 3000.0
    st = rate_state_steady(_block(k, law))
    mu = F0 + (A - B) * math.log(V / V0)
    assert st.friction_force[0] == pytest.approx(N * mu, rel=1e-14)
    assert st.x[0] == pytest.approx(N * mu / k, rel=1e-14)
    assert st.psi[0][0] == pytest.approx(math.log(V0 / V), abs=1e-15)
    assert st.effective_damping[0, 0] == pytest.approx(N * A / V, rel=1e-12)  # the direct effect, N a / V


def _written_out(k, mass, psi0, t, rtol=1e-12):
    """m x'' = -k x + N (f0 + a ln(v_r / V0) + b psi), v_r = V - x', psi' = V0/Dc e^-psi - v_r/Dc."""
    def rhs(_, y):
        vr = V - y[1]
        return [y[1], (-k * y[0] + N * (F0 + A * math.log(vr / V0) + B * y[2])) / mass,
                V0 / DC * math.exp(-y[2]) - vr / DC]
    x0 = N * (F0 + (A - B) * math.log(V / V0)) / k
    sol = solve_ivp(rhs, (0, t[-1]), [x0, 0.0, math.log(V0 / V) + psi0], method="LSODA", t_eval=t, rtol=rtol,
                    atol=[1e-16, 1e-18, 1e-12])
    return sol.y


@pytest.mark.parametrize("ratio", [0.9, 1.1])
def test_a_motion_agrees_with_solve_ivp_of_the_equations_written_out(ratio):
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    k = ratio * _kc()
    run = rate_state_simulate(_block(k, law), t_end=200.0, psi0=[math.log(V0 / V) + 0.05], samples=401)
    ref = _written_out(k, M, 0.05, run.t)
    assert np.max(np.abs(run.x[:, 0] - ref[0])) < 1e-7 * np.abs(ref[0]).max()
    assert np.max(np.abs(run.slip_rate[:, 0] - (V - ref[1]))) < 1e-5 * V
    assert np.max(np.abs(run.psi[:, 0, 0] - ref[2])) < 1e-6
    grows = np.abs(run.slip_rate[-100:, 0] - V).max() > np.abs(run.slip_rate[100:200, 0] - V).max()
    assert grows == (ratio < 1)  # below k_c the oscillation grows, above it decays


def test_two_coupled_blocks_agree_with_solve_ivp_of_the_equations_written_out():
    """Two blocks on two belts, each tied to a wall and to the other (k1, k2, kc12), with
    different laws (aging; slip with a second state variable)."""
    laws = [RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0),
            RateState(a=0.012, b=0.008, dc=2e-5, f0=0.5, v_ref=V0, evolution="slip", b2=0.006, dc2=5e-5)]
    speeds, normals = [V, 2 * V], [N, 0.5 * N]
    k1, k2, kc = 4000.0, 3000.0, 1500.0
    K = np.array([[k1 + kc, -kc], [-kc, k2 + kc]])
    sysm = System(mass=np.diag([1.0, 2.0]), stiffness=K, contacts=[
        Contact([1.0, 0.0], normals[0], laws[0], surface_speed=speeds[0]),
        Contact([0.0, 1.0], normals[1], laws[1], surface_speed=speeds[1])])
    psi0 = [[math.log(V0 / speeds[0]) + 0.03], [math.log(V0 / speeds[1]) - 0.02, math.log(V0 / speeds[1])]]
    run = rate_state_simulate(sysm, t_end=60.0, psi0=psi0, samples=201)

    def rhs(_, y):
        x, v, p = y[:2], y[2:4], y[4:]
        vr = np.array(speeds) - v
        mu0 = 0.6 + A * math.log(vr[0] / V0) + B * p[0]
        mu1 = 0.5 + 0.012 * math.log(vr[1] / V0) + 0.008 * p[1] + 0.006 * p[2]
        acc = (-K @ x + np.array([normals[0] * mu0, normals[1] * mu1])) / np.array([1.0, 2.0])
        dp = [V0 / DC * math.exp(-p[0]) - vr[0] / DC,
              -(vr[1] / 2e-5) * (p[1] + math.log(vr[1] / V0)), -(vr[1] / 5e-5) * (p[2] + math.log(vr[1] / V0))]
        return np.concatenate([v, acc, dp])

    y0 = np.concatenate([run.x[0], [0.0, 0.0], [psi0[0][0], *psi0[1]]])
    ref = solve_ivp(rhs, (0, 60.0), y0, method="LSODA", t_eval=run.t, rtol=1e-12, atol=1e-18).y
    assert np.max(np.abs(run.x - ref[:2].T)) < 1e-7 * np.abs(ref[:2]).max()
    assert np.max(np.abs(run.psi[:, 1, :] - ref[5:7].T)) < 1e-6 and np.max(np.abs(run.psi[:, 0, 0] - ref[4])) < 1e-6
    assert np.all(np.isnan(run.psi[:, 0, 1]))  # the first law has one state variable


def test_a_regularised_law_goes_through_zero_slip_rate_and_the_plain_one_says_it_cannot():
    """A block thrown forward by its spring overtakes its belt (a velocity-strengthening law)."""
    def block(regularized):
        law = RateState(a=0.02, b=0.01, dc=1e-4, f0=0.1, v_ref=1e-3, regularized=regularized)
        return System(mass=[[1.0]], stiffness=[[100.0]], contacts=[Contact([1.0], N, law, surface_speed=1e-3)])

    throw = dict(t_end=2.0, x0=[-0.1], v0=[0.5e-3], samples=401)
    with pytest.raises(NoSolutionError, match="slip rate of contact 0 fell to zero.*regularized"):
        rate_state_simulate(block(False), **throw)
    run = rate_state_simulate(block(True), **throw)
    assert run.slip_rate.min() < -0.5 and run.slip_rate.max() > 0
    moving = np.abs(run.slip_rate[:, 0]) > 1e-9
    assert np.all(np.sign(run.friction_force[moving, 0]) == np.sign(run.slip_rate[moving, 0]))  # it opposes the slip
    with pytest.raises(ParameterError, match="v0"):  # the plain law cannot start at a backward slip either
        rate_state_simulate(block(False), t_end=1.0, v0=[3e-3])


def test_bad_combinations_are_refused_with_the_names_the_user_gave():
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    with pytest.raises(ParameterError, match="rate_state_simulate"):
        simulate(_block(1e3, law), t_end=1.0)
    with pytest.raises(ParameterError, match="rate_state_steady"):
        steady_sliding(_block(1e3, law))
    pressed = Contact([1.0], N, law, surface_speed=V, normal_direction=[1.0], normal_stiffness=1.0)
    with pytest.raises(ParameterError, match=r"contacts\[0\]\.normal_direction"):
        rate_state_simulate(System(mass=[[1.0]], stiffness=[[1e3]], contacts=[pressed]), t_end=1.0)
    with pytest.raises(ParameterError, match=r"contacts\[0\]\.surface_speed"):
        rate_state_steady(System(mass=[[1.0]], stiffness=[[1e3]], contacts=[Contact([1.0], N, law)]))
    for bad in ([0.1, 0.2], [[0.1, 0.2]], ["x"], [math.nan], [1e300]):
        with pytest.raises(ParameterError, match="psi0"):
            rate_state_simulate(_block(1e3, law), t_end=1.0, psi0=bad)
    with pytest.raises(ParameterError, match="stiffness"):
        rate_state_steady(System(mass=[[1.0]], stiffness=[[0.0]], contacts=[Contact([1.0], N, law, surface_speed=V)]))
    backward = System(mass=[[1.0]], stiffness=[[1e3]], contacts=[Contact([1.0], N, law, surface_speed=-V)])
    for call in (lambda: rate_state_steady(backward), lambda: rate_state_simulate(backward, t_end=1.0)):
        with pytest.raises(ParameterError, match=r"contacts\[0\]\.surface_speed.*regularized"):
            call()
    for bad in ("0", {0: 1.0}, 0.5):
        with pytest.raises(ParameterError, match="psi0"):
            rate_state_simulate(_block(1e3, law), t_end=1.0, psi0=bad)


def test_a_toml_table_makes_a_rate_and_state_contact():
    sysm = system_from_dict({"mass": [[1.0]], "stiffness": [[3000.0]], "contact": [
        {"direction": [1.0], "normal_force": N, "surface_speed": V, "law": "rate-state", "a": A, "b": B, "dc": DC,
         "f0": F0, "v_ref": V0, "evolution": "slip"}]})
    law = sysm.contacts[0].friction
    assert isinstance(law, RateState) and (law.a, law.b, law.dc, law.evolution) == (A, B, DC, "slip")
    with pytest.raises(ParameterError, match=r"contact\[0\]\.a"):
        system_from_dict({"mass": [[1.0]], "stiffness": [[1.0]], "contact": [
            {"direction": [1.0], "normal_force": N, "law": "rate-state", "a": -1.0, "b": B, "dc": DC}]})
    with pytest.raises(ParameterError, match=r"contact\[0\]\.fs"):
        system_from_dict({"mass": [[1.0]], "stiffness": [[1.0]], "contact": [
            {"direction": [1.0], "normal_force": N, "law": "rate-state", "a": A, "b": B, "dc": DC, "fs": 0.5}]})


def test_the_run_converts_to_a_cf_dataset():
    run = rate_state_simulate(_block(3000.0, RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)), t_end=1.0, samples=11)
    ds = run.to_xarray()
    assert ds["slip_rate"].attrs["units"] == "m/s" and ds["psi"].attrs["units"] == "1"
    assert ds["x"].attrs["units"] == "m" and ds.attrs["Conventions"].startswith("CF")
