"""The two contact models the shared machinery of `stickslip.contact` serves, behind one face:
``run(params, transits, **options)``, ``scheme(params, **options)``, ``perturbed(scheme, **kw)``."""

from dataclasses import dataclass
from typing import Callable

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemScheme, integrate_fem
from stickslip.brake.fem import perturbed_steady as fem_perturbed
from stickslip.brake.ring import RingScheme, integrate, perturbed_steady


@dataclass(frozen=True)
class Model:
    name: str
    mesh: dict                 # the smallest mesh of the tests
    scheme_type: type
    integrate: Callable
    perturbed: Callable        # perturbed(scheme, amplitude, mode, noise, seed)
    units_P: str

    def scheme(self, params, **options):
        return self.scheme_type(params, **(self.mesh | options))

    def run(self, params, transits, **options):
        mesh = {k: options.pop(k, v) for k, v in self.mesh.items()}
        return self.integrate(params, **mesh, transits=transits, **options)


RING = Model("ring", {"nodes": 32}, RingScheme, integrate,
             lambda s, **kw: perturbed_steady(s.params, s.nodes, **kw), "E / M")
FEM = Model("fem", {"n_theta": 32, "n_r": 2}, FemScheme, integrate_fem, lambda s, **kw: fem_perturbed(s, **kw), "E")
MODELS = (RING, FEM)
#: Section 3.1, case 2 (f = 0.7, delta = 0.001, Omega = 50 rad/s).
CASE2 = BrakeParams.from_physical(50.0, 1e-4, 0.7)
#: Order-one coefficients; delta / sqrt(gamma) = 0.03 is small enough for separation.
ORDER_ONE = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.03, friction=0.7)
