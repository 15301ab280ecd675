"""The reduced model [12] on the ring by the method of lines, with contact and friction per node.

* `scheme`: `RingScheme`, centred differences in ``theta`` and the explicit beta2 scheme
  of `stickslip.contact` in time (its compiled step, the fully discrete growth rates);
* `integrate`: `integrate` from a perturbed steady state (`perturbed_steady`), with the
  checkpointed run books of `stickslip.contact`, returning a `RingRun`;
* `classify`: the limit regime of a run (`stickslip.contact.classify`).
"""

from ...contact import RegimeResult, classify
from .integrate import InitialCondition, RingRun, initial_from_wave, integrate, perturbed_steady, transit_time
from .scheme import RingScheme

__all__ = ["RingScheme", "InitialCondition", "RingRun", "integrate", "perturbed_steady", "transit_time",
           "RegimeResult", "classify", "initial_from_wave"]
