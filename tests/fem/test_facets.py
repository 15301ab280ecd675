"""A curved contact meshed with straight segments (issue 44): each segment's deviation from the
curve through the nodes against the closed-form sagitta ``R - sqrt(R^2 - h^2 / 4)`` of a chord
of length ``h`` on a circle of radius ``R`` (nodes on the circle, whatever their spacing), none
on a straight face; and steady sliding of a pad on a coarsely meshed disc warns (a log line
with the ratio and what to do) where the facets cost the contact pressure at nodes, and not
where the mesh is fine."""

import logging
import re
import subprocess
import sys

import numpy as np
import pytest

from stickslip.fem import read_body
from stickslip.fem.config import load_config
from stickslip.fem.facets import facet_deviation

from .meshes import annulus, rectangle
from .test_examples import EXAMPLES
from .test_pair_config import pad_disc


def test_the_facets_deviate_from_a_circle_by_their_sagitta(tmp_path):
    rng = np.random.default_rng(4)
    for radius, count in ((0.15, 200), (1.0, 40)):  # unequal segments: each its own sagitta
        angle = np.sort(rng.uniform(0.0, 2 * np.pi, count))
        points = radius * np.column_stack([np.cos(angle), np.sin(angle)]) + [0.3, -0.2]
        edges = np.column_stack([np.arange(count), np.roll(np.arange(count), -1)])
        edges = edges[rng.permutation(count)]  # in any order
        edges[::3] = edges[::3, ::-1]  # and direction
        h = np.linalg.norm(points[edges[:, 1]] - points[edges[:, 0]], axis=1)
        exact = radius - np.sqrt(radius**2 - h**2 / 4)
        assert np.abs(facet_deviation(points, edges) - exact).max() < 1e-9 * exact.max()
    annulus(tmp_path / "ring.msh", inner=1.0, outer=1.5, size=0.13)  # a mesh's circle
    body = read_body(tmp_path / "ring.msh")
    edges = body.group("rim")[:, :2]
    h = np.linalg.norm(body.points[edges[:, 1], :2] - body.points[edges[:, 0], :2], axis=1)
    assert np.abs(facet_deviation(body.points, edges) - (1.5 - np.sqrt(1.5**2 - h**2 / 4))).max() < 1e-9 * h.max()**2
    rectangle(tmp_path / "flat.msh", size=0.003)
    flat = read_body(tmp_path / "flat.msh")
    assert facet_deviation(flat.points, flat.group("bottom")).max() < 1e-12
    corner = np.concatenate([flat.group("bottom"), flat.group("right")])  # a corner is not a curve
    assert facet_deviation(flat.points, corner).max() < 1e-12


@pytest.mark.slow
def test_a_pad_on_a_coarse_disc_mesh_is_warned_of_the_facets(tmp_path, caplog):
    """A 2-mm pad pressed 20 micrometres into the disc: on a 6-mm disc mesh the facets sag
    h^2 / (8 R) = 30 micrometres and most of the face loses its pressure: warned, with the ratio;
    on a 1.5-mm mesh (1.9 micrometres) every node keeps it: no warning."""
    folder = pad_disc(tmp_path, "0.006")
    subprocess.run([sys.executable, str(EXAMPLES / "pad_on_disc" / "mesh.py"), "pad2.msh", "0.002"], cwd=folder,
                   check=True)
    text = (folder / "pad_disc.toml").read_text().replace('"pad.msh"', '"pad2.msh"')
    for size in ("0.006", "0.0015"):
        subprocess.run([sys.executable, str(EXAMPLES / "pad_on_disc" / "disc.py"), f"disc{size}.msh", size, "2e-5"],
                       cwd=folder, check=True)
        (folder / "case.toml").write_text(text.replace('"disc.msh"', f'"disc{size}.msh"'))
        caplog.clear()
        with caplog.at_level(logging.WARNING, logger="stickslip.fem"):
            steady = load_config(folder / "case.toml").problem().steady
        if size == "0.006":
            assert steady.active.mean() < 0.5
            ratio = float(re.search(r"([0-9.]+) times the", caplog.text).group(1))
            assert len(caplog.records) == 1 and ratio > 1 and "refine" in caplog.text
        else:
            assert steady.active.all() and not caplog.records
