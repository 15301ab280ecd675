"""Ready-made systems: the Burridge-Knopoff chain.

A row of ``blocks`` blocks of mass ``m`` rests on a surface; each is tied to its neighbours by
springs ``k_c`` (the ends free) and to a driving plate, moving at ``V``, by a leaf spring ``k_p``.
With ``x`` the blocks' displacements from the plate, the ground moves at ``-V`` in the plate's
frame, so every contact rubs on a surface of speed ``-V``:

    m x_i'' + k_p x_i + k_c (2 x_i - x_{i-1} - x_{i+1}) = F_i,   v_r,i = -V - x_i',

(a block sticking to the ground has ``x_i' = -V``: it falls behind the plate until its spring
pulls it free)
the discrete version of the paper's stick-slip waves (Burridge & Knopoff 1967; Carlson & Langer
1989), each block one contact of a `System`.
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError
from ..friction import FrictionLaw
from ..quantities import MAX_CONTACTS, SYSTEM as Q
from .model import Contact, System

__all__ = ["burridge_knopoff"]


def burridge_knopoff(blocks: int, friction: FrictionLaw, *, mass: float = 1.0, coupling: float = 1.0,
                     pull: float = 1.0, normal_force: float = 1.0, plate_speed: float = 0.1,
                     damping: float = 0.0) -> System:
    """The chain of ``blocks`` blocks (see the module): ``coupling`` k_c and ``pull`` k_p in N/m,
    every block on the same ``friction`` law and ``normal_force``; ``damping`` a dashpot per block
    against the plate (N s/m)."""
    if isinstance(blocks, bool) or not isinstance(blocks, (int, np.integer)) or not 1 <= blocks <= MAX_CONTACTS:
        raise ParameterError("blocks", blocks, f"a whole number of blocks from 1 to {MAX_CONTACTS}")
    mass = Q["mass_matrix"].check(mass, "mass")
    if mass <= 0:
        raise ParameterError("mass", mass, "positive")
    coupling = Q["stiffness_matrix"].check(coupling, "coupling")
    pull = Q["stiffness_matrix"].check(pull, "pull")
    damping = Q["damping_matrix"].check(damping, "damping")
    plate_speed = Q["surface_speed"].check(plate_speed, "plate_speed")
    normal_force = Q.check("normal_force", normal_force)
    if not isinstance(friction, FrictionLaw):
        raise ParameterError("friction", friction, "a stickslip.friction.FrictionLaw")
    n = int(blocks)
    laplacian = 2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)
    laplacian[0, 0] = laplacian[-1, -1] = 1.0 if n > 1 else 0.0
    contacts = [Contact(np.eye(n)[i], normal_force, friction, -plate_speed, name=f"block {i}") for i in range(n)]
    return System(mass * np.eye(n), pull * np.eye(n) + coupling * laplacian, contacts, damping=damping * np.eye(n))
