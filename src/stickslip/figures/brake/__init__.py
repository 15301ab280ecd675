"""Figures of the brake-like system (paper section 3), one module per figure.

`paper` holds the parameter sets the figures share (the three regimes of section 3.1,
the cases of Figures 5, 6, 11 and 12); `wave_cases`, `ring_runs` and `fem_cases` the
computations, checks and plots that several figures of one sub-model have in common.
"""
