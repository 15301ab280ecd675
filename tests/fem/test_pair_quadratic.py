"""A pair of bodies with quadratic cells (issue 44): refused with the reason, naming the group
(the mortar is exact for straight 2-node segments only), on the slave's side and the master's."""

import pytest

from stickslip.errors import ParameterError
from stickslip.fem import Material, assemble, read_body
from stickslip.fem.pair import PairProblem, Translation

from .meshes import rectangle


@pytest.mark.parametrize("quadratic", ["slave", "master"])
def test_quadratic_cells_in_a_pair_are_refused_with_the_reason(tmp_path, quadratic):
    rectangle(tmp_path / "upper.msh", size=0.01, origin=(0.0, 0.01), order=2 if quadratic == "slave" else 1)
    rectangle(tmp_path / "lower.msh", size=0.01, order=2 if quadratic == "master" else 1)
    upper, lower = read_body(tmp_path / "upper.msh"), read_body(tmp_path / "lower.msh")
    material = Material(1e9, 0.3, 1000.0)
    with pytest.raises(ParameterError) as err:
        PairProblem(assemble(upper, material), "bottom", assemble(lower, material), "top", Translation((1.0, 0.0)))
    assert err.value.name == f"{quadratic}_group" and err.value.value in ("bottom", "top")
    assert "quadratic" in str(err.value) and "h^2 / (8 R)" in str(err.value)
