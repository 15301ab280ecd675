"""Parameters of the brake-like system: scaling and validation."""

import json

import pytest

from stickslip.brake import STEEL, BrakeParams, PhysicalParams
from stickslip.errors import ParameterError


def test_physical_to_dimensionless():
    p = PhysicalParams(omega=50.0, mismatch=1e-4, friction=0.7, inner_radius=0.1, outer_radius=0.15)
    b = p.dimensionless()
    assert b.xi == pytest.approx(1.5)
    assert b.gamma == pytest.approx(STEEL["density"] * 0.1**2 * 50.0**2 / STEEL["young"])
    assert b.delta == pytest.approx(1e-3) and b.friction == 0.7 and b.nu == STEEL["poisson"]
    assert b.omega == 50.0 and b.physical is p
    assert BrakeParams.from_physical(50.0, 1e-4, 0.7) == b  # equality ignores the physical record
    json.dumps(b.to_dict())


def test_dimensionless_parameters_have_no_time_unit():
    b = BrakeParams(1.5, 0.3, 1e-6, 0.001, 0.5)
    assert b.physical is None and b.omega != b.omega  # nan
    assert b.replace(friction=0.2).friction == 0.2


@pytest.mark.parametrize("kwargs, name", [
    (dict(xi=1.0), "xi"), (dict(xi=float("nan")), "xi"), (dict(nu=0.5), "nu"), (dict(nu=-0.01), "nu"),
    (dict(gamma=0.0), "gamma"), (dict(delta=-1e-9), "delta"), (dict(friction=-0.1), "friction"),
    (dict(friction=True), "friction"), (dict(physical="steel"), "physical")])
def test_dimensionless_validation(kwargs, name):
    args = dict(xi=1.5, nu=0.3, gamma=1e-6, delta=1e-3, friction=0.5) | kwargs
    with pytest.raises(ParameterError) as err:
        BrakeParams(**args)
    assert err.value.name == name and name in str(err.value)


@pytest.mark.parametrize("kwargs, name", [
    (dict(omega=0.0), "omega"), (dict(mismatch=-1e-5), "mismatch"), (dict(friction=float("inf")), "friction"),
    (dict(inner_radius=-0.1), "inner_radius"), (dict(outer_radius=0.1), "outer_radius"),
    (dict(young=0.0), "young"), (dict(density=-1.0), "density"), (dict(poisson=0.5), "poisson")])
def test_physical_validation(kwargs, name):
    args = dict(omega=50.0, mismatch=1e-4, friction=0.5) | kwargs
    with pytest.raises(ParameterError) as err:
        PhysicalParams(**args)
    assert err.value.name == name
    assert isinstance(err.value, ValueError)
