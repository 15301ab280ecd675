"""stickslip: friction-induced vibration and stick-slip waves.

Models of the paper "Friction-induced vibration and stick-slip waves: short survey and
new results": the 1-DOF friction oscillator (`stickslip.oscillator`), and more.
"""

__version__ = "0.1.0"
