"""Helpers for the figure tests."""

from matplotlib.figure import Figure

from stickslip import plotting


def assert_png(plot, ds, path):
    """``plot(ds)`` returns a `Figure`, draws on a figure it is given, and saves as a PNG."""
    fig = plot(ds)
    assert isinstance(fig, Figure) and fig.axes
    given = Figure()
    assert plot(ds, given) is given and given.axes
    plotting.save(fig, path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
