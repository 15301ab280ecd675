"""The run books of both models record a consistent motion: in runs where all four node
states occur, the recorded energy changes by exactly the work of the recorded reactions on
the recorded displacements (central differences).

Signorini's and Coulomb's laws are checked on reactions recomputed from the motion in
test_motion.py, not on the kernel's own states (which satisfy them by construction)."""

import numpy as np
import pytest


from .models import MODELS, ORDER_ONE


def _every_step(model, beta2=0.5, transits=20):
    s = model.scheme(ORDER_ONE, beta2=beta2)
    spt = int(np.ceil(s.steps_per_transit))
    run = model.run(ORDER_ONE, transits, initial=model.perturbed(s, amplitude=1.0, mode=3, noise=0.1), beta2=beta2,
                    samples_per_transit=spt, snapshot_every=1.0 / spt)
    assert run.settings["chunk"] == 1 and run.state.shape[0] == run.energy.size  # every step recorded
    return run



@pytest.mark.parametrize("model", MODELS, ids=lambda m: m.name)
def test_all_four_states_occur_with_central_differences(model):
    run = _every_step(model)
    counts = np.bincount(run.state.ravel(), minlength=4) / run.state.size
    assert np.all(counts > 0.01), counts




@pytest.mark.parametrize("model", MODELS, ids=lambda m: m.name)
def test_discrete_energy_balance_is_the_work_of_the_reactions(model):
    """Central differences: ``E_{m+1/2} - E_{m-1/2} = (r_m - r_e) . M (u_{m+1} - u_{m-1}) / 2`` for the
    energy of the deviation from steady sliding (``r_e`` its reactions per unit mass)."""
    run = _every_step(model)
    s = run.scheme
    normal, _ = s.contact_dofs
    weight = np.broadcast_to(s.mass, s.sparse_operator.shape[:1])[normal] / run.FORMAT.traction_scale(s)
    _, r_n, r_t = s.steady_reference()
    scale = run.FORMAT.traction_scale(s)
    dE = np.diff(run.energy)[:-1]  # E_{m+1/2} - E_{m-1/2} for m = 1 .. M-2
    work = np.sum(weight * ((run.P[1:-1] - scale * r_n) * (run.U[2:] - run.U[:-2]) / 2
                            + (run.Q[1:-1] - scale * r_t) * (run.V[2:] - run.V[:-2]) / 2), axis=1)
    assert np.abs(dE - work).max() < 1e-10 * np.abs(run.energy).max()
    assert np.abs(work).max() > 1e-3 * np.abs(run.energy).max()  # the reactions do work
