"""Rate-and-state friction and the spring-slider.

`RateState` is the law (Dieterich aging, Ruina slip or Perrin-Rice-Zheng evolution; one or two
state variables; the regularised form near zero slip rate); `SpringSlider` a slider pulled
through a spring, quasi-static or with inertia; `slide` its response to a load-point velocity
history (velocity steps, slide-hold-slide); `linear_stability` the stability of steady sliding,
its critical stiffness and Hopf frequency; `slider_cycle` the stick-slip cycle beyond.
"""

from .law import RateState
from .slider import SliderRun, SpringSlider, load_history, slide
from .stability import SliderCycle, SliderStability, linear_stability, slider_cycle

__all__ = ["RateState", "SpringSlider", "SliderRun", "slide", "load_history", "SliderStability",
           "linear_stability", "SliderCycle", "slider_cycle"]
