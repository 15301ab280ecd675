"""Figures of `stickslip.plotting` are laid out when returned: shown as they are (a notebook
shows the figure a cell returns, without `plotting.save`), their legends stay off the other
panel; drawn into a subfigure, they leave the layout to the figure that holds it."""

from matplotlib.figure import Figure

from stickslip import plotting
from stickslip.friction import Coulomb
from stickslip.oscillator import Oscillator, limit_cycle, simulate

OSC = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Coulomb(fs=0.6, fd=0.4))


def test_cycle_and_trajectory_figures_are_legible_as_returned():
    for fig in (plotting.plot_cycle(limit_cycle(OSC).to_xarray()),
                plotting.plot_trajectory(simulate(OSC, 20.0, x0=-1.5).to_xarray(501))):
        assert plotting.legibility_problems(fig) == []


def test_a_subfigure_is_drawn_into_without_a_layout_of_its_own():
    fig = Figure(figsize=(11, 8))
    top, bottom = fig.subfigures(2, 1)
    plotting.plot_cycle(limit_cycle(OSC).to_xarray(), fig=top)
    plotting.plot_trajectory(simulate(OSC, 20.0, x0=-1.5).to_xarray(501), fig=bottom)
    assert len(fig.axes) == 4
