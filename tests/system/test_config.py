"""A system from a TOML file: the example is the docs' system, and every problem names its key."""

from pathlib import Path

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.system import load_system, simulate, system_from_dict

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "two_blocks" / "two_blocks.toml"
BASE = {"mass": [[1.0]], "stiffness": [[1.0]],
        "contact": [{"direction": [1.0], "normal_force": 1.0, "fs": 0.5, "fd": 0.3, "surface_speed": 0.2}]}


def test_the_example_file_is_the_two_block_chain_of_the_docs():
    system = load_system(EXAMPLE)
    np.testing.assert_array_equal(system.mass, np.diag([1.0, 1.5]))
    assert [c.normal_force for c in system.contacts] == [2.0, 1.0]
    run = simulate(system, t_end=12.0, samples=2)
    assert list(run.event_contact) == [1, 0, 0, 0, 0, 1, 1]


def _with(change: dict, contact: dict | None = None) -> dict:
    data = {**BASE, **change}
    if contact is not None:
        data["contact"] = [{**BASE["contact"][0], **contact}]
    return data


@pytest.mark.parametrize("data, name", [
    (_with({"masses": 1.0}), "masses"),
    (_with({}, {"fs": 0.1}), "contact[0].fs"),
    (_with({}, {"direction": [1.0, 0.0]}), "contact[0].direction"),
    (_with({}, {"friction": 0.3}), "contact[0].friction"),
    (_with({}, {"law": "viscous"}), "contact[0].law"),
    (_with({}, {"law": "stribeck"}), "contact[0].vs"),
    (_with({}, {"law": "stribeck", "vs": 0.0}), "contact[0].vs"),
    (_with({}, {"law": "coulomb", "vs": 0.1}), "contact[0].vs"),
    (_with({}, {"law": "linear-weakening"}), "contact[0].tau"),
    (_with({}, {"normal_force": -1.0}), "contact[0].normal_force"),
    (_with({}, {"normal_stiffness": 1.0}), "contact[0].normal_stiffness"),
    (_with({}, {"normal_direction": [1.0, 1.0], "normal_stiffness": 1.0}), "contact[0].normal_direction"),
    (_with({"contact": []}), "contact"),
    (_with({"mass": [[1.0, 0.0], [0.0, 1.0]]}), "stiffness"),
    (_with({"mass": [[-1.0]]}), "mass"),
    ({"mass": [[1.0]], "contact": BASE["contact"]}, "stiffness")])
def test_every_problem_names_its_key(data, name):
    with pytest.raises(ParameterError) as err:
        system_from_dict(data)
    assert err.value.name == name


def test_a_file_that_is_not_toml_is_refused(tmp_path):
    bad = tmp_path / "s.toml"
    bad.write_text("mass = [[1.0]\n")
    with pytest.raises(ParameterError, match="valid TOML"):
        load_system(bad)
    with pytest.raises(ParameterError, match="readable"):
        load_system(tmp_path / "missing.toml")


def test_the_hoffmann_example_is_the_docs_squeal_model():
    """Its file and the model of docs/systems.md written in Python give the same contact."""
    system = load_system(EXAMPLE.parents[1] / "hoffmann" / "hoffmann.toml")
    c = system.contacts[0]
    assert c.unilateral and c.normal_stiffness == 0.5 and list(c.normal_direction) == [0.0, 1.0]
    np.testing.assert_array_equal(system.stiffness, [[1.1, -0.3], [-0.3, 0.5]])
    assert (c.friction.fs, c.friction.fd, c.surface_speed) == (0.84, 0.7, 0.5)
