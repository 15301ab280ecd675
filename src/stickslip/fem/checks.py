"""The config readers' checks: each appends what is wrong, as the config writes it, to a list of
problems and returns the value or None, so that one message names every problem of a config
(`stickslip.fem.config`, `stickslip.fem.config_solid`)."""

from __future__ import annotations

from pathlib import Path

from ..errors import ParameterError
from ..quantities import FEM as Q

__all__ = ["problem_text", "number", "pair", "vector", "toml", "mesh_file", "group_list"]


def problem_text(err: ParameterError) -> str:
    """A `ParameterError` as one problem of the list: ``where = value must be ...``."""
    return f"{err.name} = {toml(err.value)} must be {err.allowed}"


def number(problems, where, value, name=None):
    """The declared quantity ``name`` (default: the key after the last dot) at ``where``."""
    q = Q[name or where.rsplit(".", 1)[-1]]
    if value is None:
        problems.append(f"{where} is missing ({q.allowed})")
        return None
    try:
        return q.check(value, where)
    except ParameterError as err:
        problems.append(problem_text(err))
        return None


def pair(problems, where, value, name=None):
    q = Q[name or where.rsplit(".", 1)[-1]]
    if value is None:
        problems.append(f"{where} is missing (two numbers [x, y], each {q.allowed})")
        return None
    try:
        return q.check_pair(value, where)
    except ParameterError as err:
        problems.append(problem_text(err))
        return None


def vector(problems, where, value, size: int, name=None):
    """``size`` numbers (a plane body's two, a solid's three) of the declared quantity at ``where``."""
    q = Q[name or where.rsplit(".", 1)[-1]]
    if value is None:
        problems.append(f"{where} is missing ({size} numbers, each {q.allowed})")
        return None
    try:
        return q.check_vector(value, where, (size,))
    except ParameterError as err:
        problems.append(problem_text(err))
        return None


def mesh_file(problems, path: Path, mesh, where: str) -> Path | None:
    """The mesh file named at ``where`` (relative to the config's folder), or None with the problem."""
    if not isinstance(mesh, str):
        problems.append(f"{where} must be the path of a mesh file")
        return None
    mesh_path = (path.parent / mesh) if not Path(mesh).is_absolute() else Path(mesh)
    if not mesh_path.is_file():
        problems.append(f"{where} = {mesh!r}: no such file ({mesh_path})")
        return None
    return mesh_path


def group_list(problems, value, where: str) -> list:
    """A list of boundary group names at ``where``, each once, or [] with the problem."""
    if isinstance(value, list) and all(isinstance(c, str) for c in value):
        twice = sorted({c for c in value if value.count(c) > 1})
        if twice:
            problems.append(f"{where} = {value!r} must name each group once ({', '.join(map(repr, twice))} twice)")
        return list(dict.fromkeys(value))
    problems.append(f"{where} = {value!r} must be a list of boundary group names")
    return []


def toml(value) -> str:
    """A value as it is written in the config."""
    return str(value).lower() if isinstance(value, bool) else repr(value)
