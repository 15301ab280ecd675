"""Compile the package's numba kernels into their cache on disk, ahead of their first use.

numba compiles a kernel at its first call, in the first process that meets it (3 to 10 s for each
compiled path on the 2-core machine), and keeps it on disk (``cache=True``): later processes load
it in a fraction of a second. ``python -m stickslip.precompile`` runs a small case of each compiled
path, in two processes at once, so that no later process pays the compilation: not a test worker,
not a figure of the reproduction, not the first command of a user. The Makefile runs it when it
builds the environment; after ``pip install stickslip`` it may be run once by hand. It writes
nothing but numba's cache and prints one line per path with its time.
"""

from __future__ import annotations

import sys
import time
from concurrent.futures import ProcessPoolExecutor

__all__ = ["PATHS", "precompile"]


def _stribeck_oscillator() -> None:
    from .friction import Stribeck
    from .oscillator import Oscillator, limit_cycle

    limit_cycle(Oscillator(1.0, 1.0, 1.0, 0.2, Stribeck(0.6, 0.4, 0.1), 0.05))


def _affine_oscillator() -> None:
    from .friction import Coulomb
    from .oscillator import Oscillator, simulate
    from .oscillator.kernel import KERNELS

    KERNELS.compiled  # noqa: B018 (loaded: every later call of this process takes them, `stickslip.jit`)
    simulate(Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4)), 100.0).to_xarray(100)  # the pieces, sampled


def _two_blocks(law) -> "object":
    from .system import Contact, System

    return System(mass=[[1.0, 0.0], [0.0, 1.5]], stiffness=[[3.0, -1.0], [-1.0, 2.0]],
                  contacts=[Contact([1.0, 0.0], 2.0, law, surface_speed=0.3),
                            Contact([0.0, 1.0], 1.0, law, surface_speed=0.1)],
                  damping=[[0.06, -0.02], [-0.02, 0.04]])


def _system_cycle() -> None:
    from .friction import Coulomb
    from .system import limit_cycle

    limit_cycle(_two_blocks(Coulomb(0.6, 0.4)), transient=60.0)


def _smooth_system() -> None:
    from .friction import Stribeck
    from .system import rate_state_simulate

    rate_state_simulate(_two_blocks(Stribeck(0.6, 0.4, 0.05)), t_end=0.5, method="compiled")


def _fe_annulus() -> None:
    from .brake import BrakeParams
    from .brake.fem import integrate_fem

    integrate_fem(BrakeParams.from_physical(50.0, 1e-4, 0.7), 64, 4, transits=0.2)


def _sbim_history() -> None:
    import numpy as np

    from .sbim.history import KERNELS, History

    h = History(np.ones(3, complex), np.array([0, 2, 1]), 2)
    h.kernels = KERNELS.compiled
    h.memory(1)
    h.push(1, np.zeros(3, complex))


def _rsf_slider() -> None:
    import numpy as np

    from .rsf import RateState, SpringSlider
    from .rsf.kernel import KERNELS, pack

    slider = SpringSlider(RateState(0.01, 0.015, 1e-5), 1e7, 1e10)
    y, p = slider.steady_state(1e-6), pack(slider, 1e-5)
    KERNELS.compiled.rhs(y, p, np.empty(y.size))
    KERNELS.compiled.jacobian(y, p, np.empty((y.size, y.size)))


#: The compiled paths, the longest to compile first: name -> a small case of it.
PATHS = {"oscillator under a law that is not affine (DOP853 with the law)": _stribeck_oscillator,
         "systems under laws that are not affine (DOP853 with the laws)": _smooth_system,
         "systems' limit cycles (the event search)": _system_cycle,
         "the FE annulus (the explicit contact step)": _fe_annulus,
         "oscillator under an affine law (closed-form pieces)": _affine_oscillator,
         "the spectral boundary integral method's convolution": _sbim_history,
         "the rate-and-state slider's equations and Jacobian": _rsf_slider}


def _timed(name: str) -> float:
    start = time.perf_counter()
    PATHS[name]()
    return time.perf_counter() - start


def precompile(workers: int = 2) -> dict[str, float]:
    """Run every path of `PATHS` in ``workers`` processes; the seconds each took."""
    with ProcessPoolExecutor(max(1, int(workers))) as pool:
        return dict(zip(PATHS, pool.map(_timed, PATHS)))


def main() -> None:
    start = time.perf_counter()
    for name, seconds in precompile().items():
        print(f"compiled in {seconds:5.1f} s: {name}", file=sys.stderr)
    print(f"numba's cache ready in {time.perf_counter() - start:.1f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
