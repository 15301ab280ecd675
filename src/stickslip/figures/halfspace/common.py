"""What the half-space figures share: the parameters of the paper's Figure 14, and checks
given as rows ``(name, passed, measured, expected, detail)``."""

from __future__ import annotations

import numpy as np

from .. import Check

__all__ = ["FIGURE14", "checks"]

FIGURE14 = dict(young=2.1e11, density=7850.0, nu=0.3, mu=0.5, mu_star=0.4, v_star=0.001, cbar=-0.7)


def checks(rows) -> list[Check]:
    """`Check` objects from rows ``(name, passed, measured, expected, detail)`` (numbers formatted)."""
    def text(x):
        if isinstance(x, (np.integer, np.floating, np.bool_)):
            x = x.item()
        return f"{x:.6g}" if isinstance(x, float) else str(x)
    return [Check(str(n), bool(p), text(m), text(e), str(d)) for n, p, m, e, d in rows]
