"""Helpers shared by the tests of the explicit contact schemes."""

import numpy as np

from stickslip.contact import StepState, kernel


def free_run(scheme, u0, nsteps, dt):
    """``nsteps`` steps of the free problem (no contact) from rest at ``u0``, at any ``dt`` (even
    beyond the CFL limit, where a scheme cannot be built): the compiled kernel called directly."""
    k = StepState(np.array(u0, dtype=float), np.zeros(len(u0)), np.zeros(len(u0)))
    out = scheme.new_output()
    (indptr, indices, data, block), (normal, tangent) = scheme.kernel_operator, scheme.contact_dofs
    gap0, speed = scheme.surface
    kernel.advance(scheme.stencil, indptr, indices, data, block, np.zeros(0), np.zeros(2), k.u, k.v, k.a, normal, tangent, gap0, speed, nsteps,
                   dt, scheme.beta2, 0.0, 0.0, False, out.lam_n, out.lam_t, out.state, out.u_prev, np.zeros(3))
    return k.u
