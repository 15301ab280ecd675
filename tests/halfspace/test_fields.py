"""Interface fields: the periodic canonical function, the closed form of [46] against its
quadrature, boundary conditions, decay, singularities and admissibility."""

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.halfspace import (StickSlipWave, decaying_velocity, decaying_wave, inverse_problem, periodic_X,
                                 radok, wave_from_inverse)

NU, MU, VS = 0.3, 0.5, 1e-3
CASES = [(2.0, -0.7), (11.358, -0.7), (1.3, -0.2), (40.0, -0.95), (5.0, -0.05)]


@pytest.fixture(params=CASES, ids=[f"b{b}-c{c}" for b, c in CASES])
def wave(request):
    b, c = request.param
    return wave_from_inverse(b, c, VS, nu=NU, mu=MU)


def test_canonical_function_jumps_and_period():
    b, c = 3.7, -0.6
    rd = radok(c, NU, MU)
    lam = float(rd.lam)
    g = -(rd.gamma1 + 1j * MU * rd.gamma2) / (rd.gamma1 - 1j * MU * rd.gamma2)
    eps = 1e-12
    x_sl, x_st = np.linspace(1.05, b - 0.05, 7), np.linspace(0.05, 0.95, 7)
    for x, jump in ((x_sl, g), (x_st, 1.0)):
        ratio = periodic_X(x + 1j * eps, b, lam) / periodic_X(x - 1j * eps, b, lam)
        np.testing.assert_allclose(ratio, jump, atol=1e-9)
    z = np.array([0.3 - 0.2j, 2.2 + 0.7j, -1.0 - 3j])
    np.testing.assert_allclose(periodic_X(z + b, b, lam), periodic_X(z, b, lam), rtol=1e-12)
    np.testing.assert_allclose(periodic_X(np.conj(z), b, lam), np.conj(periodic_X(z, b, lam)), rtol=1e-12)
    # end behaviour: |X| ~ r^-lam at b (slip -> stick), r^lam at a = 1 (stick -> slip)
    r = np.array([1e-6, 1e-7])
    sb = np.diff(np.log(np.abs(periodic_X(b - 1j * r, b, lam)))) / np.diff(np.log(r))
    sa = np.diff(np.log(np.abs(periodic_X(1.0 - 1j * r, b, lam)))) / np.diff(np.log(r))
    assert sb[0] == pytest.approx(-lam, abs=1e-6) and sa[0] == pytest.approx(lam, abs=1e-6)


def test_closed_form_equals_quadrature_of_cauchy_integral(wave):
    b = wave.b
    z = np.concatenate([np.linspace(0.05, b - 0.05, 9) - 0.1j, np.array([0.5 - 2j, b / 2 - 0.5j, b + 0.3 - 0.4j])])
    q, c = wave.phi_quadrature(z), wave.phi(z)
    assert np.max(np.abs(q - c)) / np.max(np.abs(c)) < 1e-11
    r = np.geomspace(0.1, 1e-4, 7)   # towards the singular point b
    ray = b - 1j * r
    assert np.max(np.abs(wave.phi_quadrature(ray) / wave.phi(ray) - 1)) < 1e-10


def test_quadrature_converges_towards_the_axis():
    w = wave_from_inverse(6.0, -0.5, VS, nu=NU, mu=MU)
    z = np.array([3.0 - 1e-2j, 0.5 - 1e-2j, 6.0 - 1e-3j])
    errs = [np.max(np.abs(w.phi_quadrature(z, n=n) - w.phi(z))) / np.abs(w.A) for n in (3, 6, 12)]
    assert errs[2] < 1e-3 * errs[0] and errs[2] < 1e-9


def test_boundary_values_are_the_limit_from_the_body(wave):
    x = np.concatenate([np.linspace(0.02, 0.98, 11), np.linspace(1.02, wave.b - 0.02, 11)])
    np.testing.assert_allclose(wave.phi_boundary(x), wave.phi(x - 1e-11j), rtol=1e-7)


def test_symmetry_39_holds_for_the_quadrature(wave):
    """Phi(z) = -conj(Phi(conj z)): the continuation [39] is consistent because f/X+ is real."""
    z = np.array([0.4 - 0.3j, wave.b * 0.6 - 0.2j])
    # quadrature formula evaluated in the upper half-plane, via the same kernel
    zz = np.conj(z)
    X = periodic_X(zz, wave.b, wave.lam)
    ratio = wave.phi_quadrature(z) / periodic_X(z, wave.b, wave.lam)   # Psi(z), C0 = 0
    # Psi(conj z) = -conj(Psi(z)) for a real density; then Phi(conj z) = X(conj z) Psi(conj z)
    np.testing.assert_allclose(X * (-np.conj(ratio)), -np.conj(wave.phi(z)), rtol=1e-9)


def test_slip_and_stick_conditions_hold(wave):
    f = wave.fields(n=4001)
    assert f.slip.any() and (~f.slip).any()
    assert f.slip_residual < 1e-11
    assert f.stick_residual < 1e-11
    # on ST the material moves with the rigid body: U_dot = V
    np.testing.assert_allclose(f.material_velocity[~f.slip], wave.v, rtol=1e-11)


def test_far_field_and_mean_over_a_period(wave):
    """Phi at depth = mean of Phi along any horizontal line = far_field."""
    x = np.linspace(0, wave.b, 4096, endpoint=False)
    for depth in (0.3, 2.0):
        mean = np.mean(wave.phi(x - 1j * depth))
        assert abs(mean - wave.far_field) < 1e-10 * abs(wave.A)
    deep = wave.phi(np.array([0.3 - 10j * wave.b]))[0]
    assert abs(deep - wave.far_field) < 1e-10 * abs(wave.A)


def test_decaying_wave_decays_and_keeps_u_x_periodic():
    for b, c in CASES:
        inv = inverse_problem(b, c, VS, nu=NU, mu=MU)
        w = decaying_wave(b, c, float(inv.T), VS, nu=NU, mu=MU)
        assert w.decay_residual < 1e-13
        x = np.linspace(0, w.b, 4096, endpoint=False)
        assert abs(np.mean(w.phi(x - 0.5j))) < 1e-12 * abs(w.A)   # mean u_x,x = 0: u_x periodic


def test_exact_decay_condition_agrees_with_53_at_b_2_not_with_55():
    """The periodic decay condition is R sin(pi lam/b) + (T/Gm) sin(pi lam (b-1)/b) = 0; at b = 2
    it is [53] exactly, while [55] (factor 2) leaves a stress at depth for every b."""
    for c in (-0.9, -0.7, -0.3, -0.05):
        text = wave_from_inverse(2.0, c, VS, nu=NU, mu=MU, system="text")
        assert text.decay_residual < 1e-12
        printed = wave_from_inverse(2.0, c, VS, nu=NU, mu=MU, system="printed")
        assert printed.decay_residual > 1e-2
    bb = 1 + np.geomspace(1e-3, 1e3, 50)
    for c in (-0.9, -0.5, -0.1):
        lam = float(radok(c, NU, MU).lam)
        exact = np.sin(np.pi * lam * (bb - 1) / bb) / np.sin(np.pi * lam / bb)
        ratio = exact / (bb - 1)   # [53]: 1, [55]: 1/2
        K = np.pi * lam / np.sin(np.pi * lam)
        assert np.all(ratio > 1 / K - 1e-12) and np.all(ratio < K + 1e-12) and np.min(ratio) > 0.5


def test_decaying_velocity_formula():
    b, c, T = 4.0, -0.6, 2e-3
    v = float(decaying_velocity(b, c, T, VS, nu=NU, mu=MU))
    w = StickSlipWave(b=b, cbar=c, T=T, v=v, v_star=VS, nu=NU, mu=MU)
    assert abs(w.far_field) < 1e-15


def test_singularity_exponents_on_the_axis(wave):
    b, alpha = wave.b, wave.alpha
    r = np.array([1e-7, 1e-8])
    f = wave.fields(np.concatenate([b - r, b + r]))
    s_sl = np.diff(np.log(f.sigma_yy[:2] - float(wave.rd.gamma2) * wave.R)) / np.diff(np.log(r))
    s_st = np.diff(np.log(np.abs(f.sigma_xy[2:] - float(wave.rd.gamma1) * wave.A.imag))) / np.diff(np.log(r))
    assert s_sl[0] == pytest.approx(alpha - 0.5, abs=1e-6)   # sigma_yy singular on the slip side
    assert s_st[0] == pytest.approx(alpha - 0.5, abs=1e-6)   # sigma_xy singular on the stick side
    np.testing.assert_allclose(f.sigma_yy[2:], float(wave.rd.gamma2) * wave.R, rtol=1e-12)   # sigma_yy const on ST
    k = wave.stress_intensity
    assert f.sigma_yy[1] - float(wave.rd.gamma2) * wave.R == pytest.approx(k * r[1] ** (alpha - 0.5), rel=1e-6)
    ra = np.array([1e-7, 1e-8])   # bounded at a = 1, Hoelder exponent 1/2 - alpha
    fa = wave.fields(1.0 + ra)
    d = np.abs(fa.phi - wave.A)
    assert (np.diff(np.log(d)) / np.diff(np.log(ra)))[0] == pytest.approx(0.5 - alpha, abs=1e-6)


def test_positive_singularity_and_forward_slip(wave):
    """Paper: positive singularity of sigma_yy at SL -> ST. It comes with a forward (V - U_dot > 0)
    slip velocity that is singular too; the material velocity U_dot tends to -infinity."""
    assert wave.beta0 < 0 and wave.stress_intensity > 0
    f = wave.fields(n=4001)
    assert np.all(f.slip_velocity[f.slip] > 0)
    near = wave.fields(np.array([wave.b - 1e-9]))
    assert near.Sigma_yy[0] > 0 and near.material_velocity[0] < -1 and near.slip_velocity[0] > 1


def test_tensile_zone_boundary(wave):
    x_t, end = wave.tensile_zone()
    assert end == wave.b and 1.0 < x_t < wave.b
    s = wave.fields(np.array([x_t - 1e-9 * wave.b, x_t + 1e-9 * wave.b])).Sigma_yy
    assert s[0] < 0 < s[1]
    f = wave.fields(n=20001)
    tensile = f.x[(f.Sigma_yy > 0)]
    assert tensile.min() >= x_t - 1e-12 and np.all(f.slip[f.Sigma_yy > 0])


def test_stick_violation_intervals_match_a_grid_scan(wave):
    f = wave.fields(np.linspace(0, 1, 200001)[1:-1])
    ok = np.abs(f.Sigma_xy) <= -wave.mu * f.Sigma_yy
    bad = f.x[~ok]
    intervals = wave.stick_violation()
    inside = np.zeros_like(f.x, dtype=bool)
    for lo, hi in intervals:
        inside |= (f.x >= lo) & (f.x <= hi)
    mismatch = np.flatnonzero(inside != ~ok)
    assert mismatch.size <= 2 * len(intervals)   # only at the interval ends
    assert bad.size == 0 or intervals


def test_corrected_48_is_continuous_at_the_stick_to_slip_point():
    """[47]-[48] with a generic |X| (X = 0 at a): [47] meets the corrected [48] at x = a; the
    printed [48] jumps by 2 T/gamma1 in Im Phi, which a Cauchy integral cannot do at a bounded end."""
    w = wave_from_inverse(3.0, -0.6, VS, nu=NU, mu=MU)
    rd = w.rd
    g1, g2, al, T = float(rd.gamma1), float(rd.gamma2), w.alpha, w.T
    f1 = -2 * w.R
    tan = MU * g2 / g1

    def phi47(X):
        return (-f1 / 2 * (1 - X) + T / g1 * np.cos(np.pi * al) * X
                + 1j * (-f1 / 2 * tan * (X - 1) + T / g1 * (1 - X * np.sin(np.pi * al))))

    def phi48(X, sign):
        return -f1 / 2 - 1j * (-f1 / 2 * tan + f1 / (2 * np.cos(np.pi * al)) * X + sign * T / g1 * (1 - X))

    X = np.linspace(0, 3, 7)
    ph = phi47(X)
    assert np.max(np.abs(g1 * ph.imag + MU * g2 * ph.real - T)) < 1e-12 * T   # [47] satisfies [40]
    assert np.max(np.abs(phi48(X, +1).real - w.R)) < 1e-15                     # [48]: stick holds
    assert abs(phi47(0.0) - phi48(0.0, -1)) < 1e-15                               # corrected: continuous
    assert abs(phi47(0.0) - phi48(0.0, +1)) == pytest.approx(2 * T / g1, rel=1e-12)   # printed: jump
    # and the corrected pair is our A' + i beta0 X-, with the beta0 implied by [47]
    beta0 = w.R / np.cos(np.pi * al) - T / g1
    assert np.max(np.abs(phi48(X, -1) - (w.A + 1j * beta0 * X))) < 1e-15
    assert np.max(np.abs(phi47(X) - (w.A + 1j * beta0 * X * np.exp(1j * np.pi * w.lam)))) < 1e-15


@pytest.mark.parametrize("kwargs, name", [
    (dict(b=1.0), "b"), (dict(T=0.0), "T"), (dict(v=VS), "v"), (dict(cbar=-1.5), "c"),
    (dict(tau_yy=0.1), "tau_yy"), (dict(nu=0.6), "nu"),
])
def test_wave_rejects_bad_input(kwargs, name):
    args = dict(b=3.0, cbar=-0.5, T=1e-3, v=4e-3, v_star=VS, nu=NU, mu=MU) | kwargs
    with pytest.raises(ParameterError) as err:
        StickSlipWave(**args)
    assert err.value.name == name


def test_potential_only_in_the_body():
    w = wave_from_inverse(3.0, -0.5, VS, nu=NU, mu=MU)
    with pytest.raises(ParameterError, match="z"):
        w.phi(np.array([1.0 + 0.1j]))
    with pytest.raises(ParameterError, match="z"):
        w.phi_quadrature(np.array([1.0 + 0.0j]))


def test_fields_dataset_has_units():
    w = wave_from_inverse(3.0, -0.5, VS, nu=NU, mu=MU)
    ds = w.fields(n=101).to_xarray()
    assert all("units" in ds[v].attrs or "flag_values" in ds[v].attrs for v in ds.data_vars)
    assert ds.attrs["slip_residual"] < 1e-11 and "tensile_zone_length" in ds.attrs
