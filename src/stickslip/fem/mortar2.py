"""The mortar coupling (`stickslip.fem.pair`) of bodies with quadratic cells: curved 3-node
segments (ends ``a``, ``b`` and the middle node ``m``), or a quadratic body on a linear one.

On a segment of parameter ``eta`` in [0, 1] the shape functions are ``N_a = (1 - eta)(1 - 2 eta)``,
``N_b = eta (2 eta - 1)``, ``N_m = 4 eta (1 - eta)`` (``1 - eta``, ``eta`` on a 2-node one), the
position ``x(eta) = sum N_k x_k`` and the line element ``J = |x'(eta)|``. The slave's dual
multipliers ``phi_j = sum_k A_jk N_k`` with ``A = D_e M_e^-1`` (``M_e = int N N^T J``, ``D_e`` its
row sums' diagonal ``int N J``: all positive on a segment) are biorthogonal to the ``N_k``, so
``D_jk = int phi_j N_k J = delta_jk int N_j J`` stays diagonal, node by node, as for straight
segments. A slave point ``x(eta)`` meets the master where ``x_m(xi) = x(eta) + alpha n(eta)``
(``n`` the slave's normal there; Newton), and ``M_jl = int phi_j N_l(xi(eta)) J deta`` over each
stretch where a master segment faces it (its ends found by Newton too), by 6-point Gauss: exact
for a straight interface (the integrands are polynomials of degree at most 8 there: the
contact patch test passes exactly), converged to round-off on curved ones at the meshes'
curvatures. The nodal normal is the mean of the segments' normals at the node, weighted by
``int N_j J``.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ..errors import ParameterError

__all__ = ["quadratic_mortar"]

_G, _W = np.polynomial.legendre.leggauss(6)
GAUSS, WEIGHTS = 0.5 * (_G + 1.0), 0.5 * _W


def shapes(eta, nodes: int):
    """``(N, dN/deta)`` at ``eta`` (arrays ``(nodes, len(eta))``) of a segment of 2 or 3 nodes."""
    eta = np.atleast_1d(np.asarray(eta, float))
    if nodes == 2:
        return np.array([1.0 - eta, eta]), np.array([-np.ones_like(eta), np.ones_like(eta)])
    return (np.array([(1 - eta) * (1 - 2 * eta), eta * (2 * eta - 1), 4 * eta * (1 - eta)]),
            np.array([4 * eta - 3, 4 * eta - 1, 4 - 8 * eta]))


def _frame(points, edge, eta):
    """Position, tangent (dx/deta) and unit normal (to the left of the tangent: into the body of
    an edge oriented as in its cell) at ``eta``."""
    N, dN = shapes(eta, len(edge))
    x, dx = (N.T @ points[edge]), (dN.T @ points[edge])
    n = np.column_stack([-dx[:, 1], dx[:, 0]])
    return x, dx, n / np.hypot(n[:, 0], n[:, 1])[:, None]


def _meet(points, edge, x, n, xi):
    """``(xi, alpha)``: where the master segment ``edge`` meets the line ``x + alpha n`` (Newton
    from ``xi``); ``xi`` NaN if it does not converge."""
    alpha = 0.0
    for _ in range(30):
        N, dN = shapes(xi, len(edge))
        r = (N.T @ points[edge])[0] - x - alpha * n
        jac = np.column_stack([(dN.T @ points[edge])[0], -n])
        try:
            step = np.linalg.solve(jac, -r)
        except np.linalg.LinAlgError:
            return np.nan, np.nan
        xi, alpha = xi + step[0], alpha + step[1]
        if abs(step[0]) < 1e-14 and abs(step[1]) < 1e-14 * (1.0 + abs(alpha)):
            return xi, alpha
    return np.nan, np.nan


def _foot(points, edge, target, eta):
    """The ``eta`` of the slave segment ``edge`` whose normal line passes through ``target``."""
    for _ in range(30):
        N, dN = shapes(eta, len(edge))
        x, dx = (N.T @ points[edge])[0], (dN.T @ points[edge])[0]
        d2 = (np.array([4.0, 4.0, -8.0]) @ points[edge]) if len(edge) == 3 else np.zeros(2)
        f = (target - x) @ dx
        df = -dx @ dx + (target - x) @ d2
        step = -f / df
        eta += step
        if abs(step) < 1e-14:
            break
    return eta


def quadratic_mortar(slave_body, s_edges, master_body, m_edges, reach: float):
    """``(nodes, normal, D, M, deep, away, found)`` of the slave's oriented ``s_edges`` and the
    master's ``m_edges`` (2 or 3 nodes each; see the module docstring); ``reach`` as in
    `stickslip.fem.pair.mortar`: the farthest gap [m] a master segment may face a slave one at."""
    xs, xm = slave_body.points[:, :2], master_body.points[:, :2]
    nodes = np.unique(s_edges)
    where = {int(v): k for k, v in enumerate(nodes)}
    normal = np.zeros((len(nodes), 2))
    Dr, Dc, Dv, Mr, Mc, Mv = [], [], [], [], [], []
    deep, away, found = 0.0, 0, 0
    m_mid = np.array([_frame(xm, e, 0.5)[0][0] for e in m_edges])
    m_nrm = np.array([_frame(xm, e, 0.5)[2][0] for e in m_edges])  # into the master
    for edge in s_edges:
        x, dx, n = _frame(xs, edge, GAUSS)
        J = np.hypot(dx[:, 0], dx[:, 1])
        N, _ = shapes(GAUSS, len(edge))
        mass = (N * (WEIGHTS * J)) @ N.T
        integral = mass.sum(axis=1)  # int N_j J: all positive
        if np.any(integral <= 0):
            raise ParameterError("slave_group", "", "segments whose nodes run along them (a middle node off its "
                                 "segment's middle third folds it)")
        A = np.diag(integral) @ np.linalg.inv(mass)
        for k, j in enumerate(edge):
            Dr.append(where[int(j)])
            Dc.append(int(j))
            Dv.append(integral[k])
            at = np.array([0.0, 1.0, 0.5][k])
            normal[where[int(j)]] += integral[k] * _frame(xs, edge, at)[2][0]
        length = float(WEIGHTS @ J)
        chord = xs[edge[1]] - xs[edge[0]]
        t = chord / np.hypot(*chord)
        # candidates: master segments whose ends' projections on the chord overlap it, within reach
        ends = (xm[m_edges[:, :2]] - xs[edge[0]]) @ t / np.hypot(*chord)
        near = np.abs((m_mid - xs[edge[0]]) @ np.array([-t[1], t[0]])) <= reach + length
        overlap = near & (np.minimum(1.0, ends.max(axis=1)) - np.maximum(0.0, ends.min(axis=1)) > -0.1)
        for f in np.flatnonzero(overlap):
            me = m_edges[f]
            e0 = _foot(xs, edge, xm[me[0]], float(np.clip(ends[f, 0], 0, 1)))
            e1 = _foot(xs, edge, xm[me[1]], float(np.clip(ends[f, 1], 0, 1)))
            lo, hi = max(0.0, min(e0, e1)), min(1.0, max(e0, e1))
            if not hi - lo > 1e-12:
                continue
            xc, _, nc = _frame(xs, edge, 0.5 * (lo + hi))
            xi, alpha = _meet(xm, me, xc[0], nc[0], 0.5)
            gap = -alpha
            if np.isnan(xi) or abs(gap) > reach or not -1e-9 <= xi <= 1 + 1e-9:
                if not np.isnan(xi) and gap < -reach and m_nrm[f] @ nc[0] < 0.0 and 0.0 <= xi <= 1.0:
                    deep = min(deep, gap)
                continue
            if m_nrm[f] @ nc[0] >= 0.0:  # a master segment facing away
                away += 1
                continue
            found += 1
            eta = lo + GAUSS * (hi - lo)
            xq, dq, nq = _frame(xs, edge, eta)
            Jq = np.hypot(dq[:, 0], dq[:, 1]) * WEIGHTS * (hi - lo)
            phi = A @ shapes(eta, len(edge))[0]
            guess = np.clip((eta - e0) / (e1 - e0), 0.0, 1.0)  # xi = 0 at e0, 1 at e1
            for q in range(len(eta)):
                xi, _ = _meet(xm, me, xq[q], nq[q], float(guess[q]))
                Nm = shapes(xi, len(me))[0][:, 0]
                for kj, j in enumerate(edge):
                    for kl, l in enumerate(me):
                        Mr.append(where[int(j)])
                        Mc.append(int(l))
                        Mv.append(Jq[q] * phi[kj, q] * Nm[kl])
    normal /= np.hypot(normal[:, 0], normal[:, 1])[:, None]
    D = sp.csr_matrix((Dv, (Dr, Dc)), shape=(len(nodes), len(xs)))
    M = sp.csr_matrix((Mv, (Mr, Mc)), shape=(len(nodes), len(xm)))
    return nodes, normal, D, M, deep, away, found
