"""Runs of a general body: the shared books in SI units, a killed run resumes bitwise, a
checkpoint of another problem is refused, the files follow the CF rules, and on the annulus
the general path finds the limit regime the annulus' own path finds."""

import numpy as np
import pytest

from stickslip.brake.fem import FemScheme, classify_fem, integrate_fem
from stickslip.errors import ParameterError
from stickslip.fem.run import BodyRun, classify_body, integrate_body

from ..cf_rules import problems
from .test_scheme import PARAMS, general_annulus


@pytest.fixture(scope="module")
def annulus():
    return general_annulus(FemScheme(PARAMS, 32, 2, 0.9)).params


def test_a_killed_run_resumes_bitwise_and_another_problem_is_refused(annulus, tmp_path):
    whole = integrate_body(annulus, transits=8.0)
    path = tmp_path / "run.nc"

    def kill(t, t_end):
        if t > 0.4 * t_end:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        integrate_body(annulus, transits=8.0, checkpoint=path, progress=kill)
    resumed = integrate_body(annulus, transits=8.0, checkpoint=path)
    assert resumed.complete and np.array_equal(resumed.U, whole.U) and np.array_equal(resumed.energy, whole.energy)
    other = type(annulus)(annulus.system, annulus.frames, 0.3, annulus.clamped)
    with pytest.raises(ParameterError) as err:
        integrate_body(other, transits=8.0, checkpoint=path)
    assert err.value.name == "checkpoint"
    back = BodyRun.from_xarray(resumed.to_xarray(), resumed.scheme)
    assert np.array_equal(back.P, resumed.P)
    assert problems(resumed.to_xarray(), "body run") == []
    assert resumed.to_xarray()["t"].attrs["units"] == "s"


def test_the_general_path_finds_the_annulus_regime(annulus):
    """The same mesh and material through both paths, from different noise: the limit regime
    and its number of waves are a property of the problem, not of the start."""
    general = classify_body(integrate_body(annulus, transits=40.0))
    own = classify_fem(integrate_fem(PARAMS, 32, 2, transits=40.0))
    assert general.regime == own.regime and general.n == own.n
