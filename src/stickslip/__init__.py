"""stickslip: friction-induced vibration and stick-slip waves.

Models of the paper "Friction-induced vibration and stick-slip waves: short survey and
new results": the 1-DOF friction oscillator (`stickslip.oscillator`), and more.
"""

try:  # written at install from the git tag (hatch-vcs): the one source of the version
    from .version import __version__
except ImportError:  # a source tree that was never installed
    __version__ = "0+unknown"
