"""Figures of the one-degree-of-freedom friction oscillator (paper section 2)."""
