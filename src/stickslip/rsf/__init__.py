"""Rate-and-state friction and the spring-slider.

`RateState` is the law (Dieterich aging, Ruina slip or Perrin-Rice-Zheng evolution; one or two
state variables; the regularised form near zero slip rate); `SpringSlider` a slider pulled
through a spring, quasi-static or with inertia; `slide` its response to a load-point velocity
history (velocity steps, slide-hold-slide); `linear_stability` the stability of steady sliding,
its critical stiffness and Hopf frequency; `hopf_criticality` whether the Hopf bifurcation there is
sub- or supercritical (its first Lyapunov coefficient); `slider_cycle` the stick-slip cycle beyond;
`fit_record` a, b, D_c, the stiffness and f0 of a laboratory record (`read_record`), with their errors.
"""

from .law import RateState
from .slider import SliderRun, SpringSlider, load_history, slide
from .stability import SliderCycle, SliderStability, linear_stability, slider_cycle
from .hopf import HopfCriticality, first_lyapunov_coefficient, hopf_criticality
from .fit import Record, RsfFit, fit_record, read_record, record_from_arrays

__all__ = ["RateState", "SpringSlider", "SliderRun", "slide", "load_history", "SliderStability",
           "linear_stability", "SliderCycle", "slider_cycle", "HopfCriticality", "hopf_criticality",
           "first_lyapunov_coefficient", "Record", "RsfFit", "fit_record", "read_record", "record_from_arrays"]
