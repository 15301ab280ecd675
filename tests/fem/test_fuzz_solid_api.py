"""Fuzzing the Python API of the 3-D bodies (issue 45), as `tests/test_fuzz_api.py` fuzzes the rest:
each public parameter, one bad value at a time (NaN, infinities, 0, -1, 1e300, 1e-300, a subnormal,
text, None, a bool, a list, a complex, a huge integer), must give a result or a `ParameterError` /
`NoSolutionError`, never another exception type."""

import pytest

from stickslip.fem import Load, Material, OrthotropicSolid
from stickslip.fem.pair import PairProblem, Translation
from stickslip.fem.solid import assemble_solid, solid_from_meshio, solid_modes, solid_supports, supported_dofs
from stickslip.fem.supports import direction_of

from ..test_fuzz_api import each_bad_value
from .test_solid_pair import H, LINING, STEEL, T, solid_mesh

_MADE: dict = {}


def _made():
    """A pad on a block, its CEA with shapes and a reduction basis, made once."""
    if not _MADE:
        from stickslip.fem.cea import complex_eigenvalues
        from stickslip.fem.reduced import modal_basis

        pad = solid_from_meshio(solid_mesh((2, 2, 1), "tetra", T, lift=H - 2e-7), "pad", units="m")
        base = solid_from_meshio(solid_mesh((2, 2, 2), "tetra", H), "block", units="m")
        problem = PairProblem(assemble_solid(pad, LINING), "z0", assemble_solid(base, STEEL), "z1",
                              Translation((1.0, 0.0)), friction=0.3, clamped_slave=("z1",), clamped_master=("z0",))
        _MADE.update(pad=pad, base=base, problem=problem,
                     modes=complex_eigenvalues(problem, (0.0, 60e3), 20, mode_shapes=True),
                     basis=modal_basis(problem, 20))
    return _MADE


ORTHO = dict(e1=9e9, e2=6e9, e3=3e9, nu12=0.25, nu13=0.2, nu23=0.15, g12=2.5e9, g13=1.5e9, g23=1.2e9, density=2400.0)


def _pair(**k):
    m = _made()
    args = dict(slave=m["problem"].slave, slave_group="z0", master=m["problem"].master, master_group="z1",
                motion=Translation((1.0, 0.0)), friction=0.3, clamped_slave=("z1",), clamped_master=("z0",))
    return PairProblem(**{**args, **k})


def _reduced(name, **k):
    from stickslip.fem import reduced

    m = _made()
    if name == "modal_basis":
        return reduced.modal_basis(**{"problem": m["problem"], "count": 10, **k})
    if name == "reduced_modes":
        return reduced.reduced_modes(**{"basis": m["basis"], **k})
    return reduced.reduced_sweep(**{"basis": m["basis"], "frictions": [0.0, 0.5], **k})


def _config_basis(**k):
    from types import SimpleNamespace

    from stickslip.fem.reduced import config_basis

    config = SimpleNamespace(reduced={"count": 10, "augment": "modes"}, cea_options={})  # a config's [cea]
    return config_basis(**{"config": config, "problem": _made()["problem"], **k})


def _shares(**k):
    from stickslip.fem.shares import energy_shares

    m = _made()
    return energy_shares(**{"problem": m["problem"], "modes": m["modes"], **k})


def _uff(**k):
    import tempfile

    from stickslip.fem.uff import write_modes_uff

    m = _made()
    return write_modes_uff(**{"problem": m["problem"], "modes": m["modes"], "path": tempfile.mkdtemp() + "/m.uff",
                              **k})


def _scheme(**k):
    from stickslip.fem.pair_run3 import SolidPairScheme

    return SolidPairScheme(**{"params": _made()["problem"], **k})


def _stress(**k):
    import numpy as np

    from stickslip.fem.solid_stress import solid_stress

    system = _made()["problem"].slave
    return solid_stress(**{"system": system, "u": np.zeros(system.n_dofs), **k})


def _spun(**k):
    from stickslip.fem.prestress import centrifugal_stiffness

    return centrifugal_stiffness(**{"system": _made()["problem"].master, "omega": 10.0,
                                    "held": supported_dofs(_made()["base"], ("z0",)), **k})


def _faces(**k):
    import numpy as np

    from stickslip.fem.facets import face_deviation

    pad = _made()["pad"]
    return face_deviation(**{"points": pad.points, "faces": np.asarray(pad.faces["z0"]), **k})


CALLS = {
    "Material loss_factor": (lambda **k: Material(**{"young": 1e10, "poisson": 0.3, "density": 2500.0, **k}),
                             ["loss_factor"]),
    "OrthotropicSolid": (lambda **k: OrthotropicSolid(**{**ORTHO, **k}),
                         [*ORTHO, "axis1", "axis2", "alpha", "beta", "loss_factor"]),
    "solid_from_meshio": (lambda **k: solid_from_meshio(**{"mesh": solid_mesh((1, 1, 1), "tetra", T), "units": "m",
                                                           **k}), ["mesh", "source", "units"]),
    "assemble_solid": (lambda **k: assemble_solid(**{"solid": _made()["pad"], "material": LINING,
                                                     "loads": [Load("z1", pressure=1e6)], **k}),
                       ["solid", "material", "loads"]),
    "supported_dofs": (lambda **k: supported_dofs(**{"solid": _made()["pad"], "clamped": ("z1",), **k}),
                       ["solid", "clamped", "rollers"]),
    "solid_supports": (lambda **k: solid_supports(**{"solid": _made()["pad"], "clamped": ("z1",),
                                                     "rollers": {"x0": [0.6, 0.8, 0.0]}, **k}),
                       ["solid", "clamped", "rollers"]),
    "direction_of": (lambda **k: direction_of(**{"value": [0.6, 0.8, 0.0], "dimension": 3, "option": "rollers.x0",
                                                 **k}), ["value"]),
    "solid_modes slanted": (lambda **k: solid_modes(**{"system": _made()["problem"].slave, "held": solid_supports(
        _made()["pad"], ("z1",), {"x0": [0.6, 0.8, 0.0]}), **k}), ["held", "count"]),
    "solid_modes": (lambda **k: solid_modes(**{"system": _made()["problem"].slave,
                                               "held": supported_dofs(_made()["pad"], ("z1",)), **k}),
                    ["system", "held", "count", "mass"]),
    "PairProblem solids": (_pair, ["slave", "slave_group", "master", "master_group", "motion", "friction",
                                   "clamped_slave", "clamped_master", "gyroscopic", "static_friction",
                                   "rollers_slave", "rollers_master", "transverse_damping", "prestress"]),
    "SolidPairScheme": (_scheme, ["params", "beta2", "courant", "time_step"]),
    "solid_stress": (_stress, ["system", "u"]),
    "centrifugal_stiffness": (_spun, ["system", "omega", "center", "held"]),
    "face_deviation": (_faces, ["points", "faces"]),
    "modal_basis": (lambda **k: _reduced("modal_basis", **k), ["problem", "count", "penalty", "augment"]),
    "reduced_modes": (lambda **k: _reduced("reduced_modes", **k), ["basis", "friction", "band", "mode_shapes"]),
    "reduced_sweep": (lambda **k: _reduced("reduced_sweep", **k), ["basis", "frictions", "band", "tol"]),
    "config_basis": (lambda **k: _config_basis(**k), ["config", "problem"]),
    "energy_shares": (_shares, ["problem", "modes"]),
    "write_modes_uff": (_uff, ["problem", "modes", "path"]),
}
CASES = [(name, param) for name, (_, params) in CALLS.items() for param in params]


@pytest.mark.parametrize("name, param", CASES, ids=[f"{n} {p}" for n, p in CASES])
def test_bad_values_give_a_parameter_error_or_a_result(name, param, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    each_bad_value(CALLS[name][0], param, name)
