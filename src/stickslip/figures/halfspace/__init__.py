"""Figures of the rigid body sliding on an elastic half-space (paper sections 4-5)."""
