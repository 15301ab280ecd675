"""From a STEP file to a brake's steady sliding on the command line (issue 45): `stickslip fem mesh`
meshes the example's STEP (drawn in millimetres) into the pad and the disc, its config reads them in
metres, and `stickslip fem steady` carries the piston's load: 1 MPa on 80 mm x 40 mm, 3200 N
(equilibrium; threshold, set before the run: 1e-8). A STEP of surfaces only, a face group on no
surface, an existing mesh without --overwrite: one line, exit 2, nothing written."""

import json
import sys
from pathlib import Path

import pytest

from stickslip.cli import run

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "brake3d"))
import brake  # noqa: E402  (the example's STEP and config)


def test_a_brake_from_its_step_on_the_command_line_carries_the_piston_s_load(tmp_path, capsys):
    step = brake.write_step(tmp_path / "brake.step")
    capsys.readouterr()  # (OpenCASCADE's STEP writer prints)
    top = brake.DISC / 1000
    assert run(["fem", "mesh", str(step), str(tmp_path / "pad.msh"), "--size", "0.012", "--solid", "solid2",
                "--solid", "solid3", "--face", f"friction=z:{top}", "--face",
                f"piston=z:{top + (brake.LINING + brake.BACKPLATE) / 1000}", "--json"]) == 0
    pad = json.loads(capsys.readouterr().out)
    assert pad["cell_groups"] == ["solid2", "solid3"] and pad["extent"] == pytest.approx([0.08, 0.04, 0.015])
    assert run(["fem", "mesh", str(step), str(tmp_path / "disc.msh"), "--size", "0.025", "--solid", "solid1",
                "--face", f"rubbing=z:{top}", "--face", f"bore=r:{brake.BORE / 1000}", "--json"]) == 0
    capsys.readouterr()
    config = brake.write_config(tmp_path)
    assert run(["fem", "steady", str(config), "--json"]) == 0
    steady = json.loads(capsys.readouterr().out)
    assert steady["normal_load"] == pytest.approx(1e6 * 0.08 * 0.04, rel=1e-8)


def test_a_step_without_solids_and_a_face_on_nothing_are_refused_in_one_line(tmp_path, capsys):
    import gmsh

    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setString("Geometry.OCCTargetUnit", "MM")
        gmsh.model.occ.addRectangle(0, 0, 0, 10, 5)
        gmsh.model.occ.synchronize()
        gmsh.write(str(tmp_path / "sheet.step"))
    finally:
        gmsh.finalize()
    capsys.readouterr()
    out = tmp_path / "m.msh"
    assert run(["fem", "mesh", str(tmp_path / "sheet.step"), str(out), "--size", "0.01"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "at least one solid" in err and not out.exists()
    step = brake.write_step(tmp_path / "brake.step")
    capsys.readouterr()
    assert run(["fem", "mesh", str(step), str(out), "--size", "0.02", "--face", "top=z:0.5"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "faces[top]" in err and not out.exists()
    assert run(["fem", "mesh", str(step), str(out), "--size", "0.02", "--face", "top=w:0.5"]) == 2
    assert "--face" in capsys.readouterr().err
