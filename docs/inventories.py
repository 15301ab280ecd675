"""Intersphinx inventories written here, for a build without the internet.

Sphinx links ``xarray.Dataset`` to xarray's documentation through the inventory
(``objects.inv``) that site publishes; this machine, like our CI, reaches only the package
registries, so the inventories cannot be downloaded. `write_inventories` writes them instead,
listing the names our docstrings and pages use with their pages in each library's documentation
(the links point to the real sites). A name missing here is set as code, not linked.
"""

from __future__ import annotations

import zlib
from pathlib import Path

#: Project -> (its documentation's root, {name: (role, page and anchor under the root)}).
LIBRARIES = {
    "python": ("https://docs.python.org/3/", {
        "pathlib.Path": ("class", "library/pathlib.html#pathlib.Path"),
        "collections.abc.Callable": ("class", "library/collections.abc.html#collections.abc.Callable"),
        "collections.abc.Sequence": ("class", "library/collections.abc.html#collections.abc.Sequence"),
        "typing.Callable": ("data", "library/typing.html#typing.Callable"),
        "float": ("class", "library/functions.html#float"),
        "int": ("class", "library/functions.html#int"),
        "bool": ("class", "library/functions.html#bool"),
        "str": ("class", "library/stdtypes.html#str"),
        "dict": ("class", "library/stdtypes.html#dict"),
        "list": ("class", "library/stdtypes.html#list"),
        "tuple": ("class", "library/stdtypes.html#tuple"),
        "ValueError": ("exception", "library/exceptions.html#ValueError"),
        "RuntimeError": ("exception", "library/exceptions.html#RuntimeError"),
    }),
    "numpy": ("https://numpy.org/doc/stable/", {
        "numpy.ndarray": ("class", "reference/generated/numpy.ndarray.html#numpy.ndarray"),
        "numpy.random.Generator": ("class", "reference/random/generator.html#numpy.random.Generator"),
        "numpy.float64": ("class", "reference/arrays.scalars.html#numpy.float64"),
    }),
    "scipy": ("https://docs.scipy.org/doc/scipy/", {
        "scipy.integrate.solve_ivp": ("function", "reference/generated/scipy.integrate.solve_ivp.html"
                                                  "#scipy.integrate.solve_ivp"),
        "scipy.sparse.csr_matrix": ("class", "reference/generated/scipy.sparse.csr_matrix.html"
                                             "#scipy.sparse.csr_matrix"),
        "scipy.sparse.spmatrix": ("class", "reference/generated/scipy.sparse.spmatrix.html#scipy.sparse.spmatrix"),
        "scipy.sparse.linalg.eigs": ("function", "reference/generated/scipy.sparse.linalg.eigs.html"
                                                 "#scipy.sparse.linalg.eigs"),
    }),
    "xarray": ("https://docs.xarray.dev/en/stable/", {
        "xarray.Dataset": ("class", "generated/xarray.Dataset.html#xarray.Dataset"),
        "xarray.DataArray": ("class", "generated/xarray.DataArray.html#xarray.DataArray"),
        "xarray.open_dataset": ("function", "generated/xarray.open_dataset.html#xarray.open_dataset"),
    }),
    "matplotlib": ("https://matplotlib.org/stable/", {
        "matplotlib.figure.Figure": ("class", "api/_as_gen/matplotlib.figure.Figure.html#matplotlib.figure.Figure"),
        "matplotlib.axes.Axes": ("class", "api/_as_gen/matplotlib.axes.Axes.html#matplotlib.axes.Axes"),
    }),
    "skfem": ("https://scikit-fem.readthedocs.io/en/latest/", {
        "skfem.mesh.Mesh": ("class", "api.html#skfem.mesh.Mesh"),
        "skfem.Mesh": ("class", "api.html#skfem.mesh.Mesh"),
        "skfem.assembly.Basis": ("class", "api.html#skfem.assembly.Basis"),
        "skfem.assembly.CellBasis": ("class", "api.html#skfem.assembly.CellBasis"),
        "skfem.CellBasis": ("class", "api.html#skfem.assembly.CellBasis"),
        "skfem.assembly.FacetBasis": ("class", "api.html#skfem.assembly.FacetBasis"),
        "skfem.FacetBasis": ("class", "api.html#skfem.assembly.FacetBasis"),
    }),
    "meshio": ("https://github.com/nschloe/meshio/", {  # meshio's documentation is its README
        "meshio.Mesh": ("class", "#readme"),
        "meshio.read": ("function", "#readme"),
    }),
    "distributed": ("https://distributed.dask.org/en/stable/", {
        "distributed.Client": ("class", "api.html#distributed.Client"),
        "dask.distributed.Client": ("class", "api.html#distributed.Client"),
    }),
}


def write_inventories(folder: Path) -> dict[str, tuple[str, str]]:
    """Write ``<project>.inv`` (Sphinx inventory format 2) for each project of `LIBRARIES` in
    ``folder``; return the ``intersphinx_mapping`` that reads them."""
    folder.mkdir(parents=True, exist_ok=True)
    mapping = {}
    for project, (root, names) in LIBRARIES.items():
        lines = [f"{name} py:{role} 1 {uri} -" for name, (role, uri) in sorted(names.items())]
        header = (f"# Sphinx inventory version 2\n# Project: {project}\n# Version: \n"
                  "# The remainder of this file is compressed using zlib.\n")
        path = folder / f"{project}.inv"
        path.write_bytes(header.encode() + zlib.compress(("\n".join(lines) + "\n").encode()))
        mapping[project] = (root, str(path))
    return mapping
