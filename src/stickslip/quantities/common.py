"""Quantities every model shares: counters and labels of results, the settings of the shared
explicit scheme (`stickslip.contact`), sweeps and tolerances. A model's own declaration of a
name (its `transits`, its `t`) takes precedence over this one."""

from __future__ import annotations

from .core import Domain, declare as Q

#: The most worker processes a sweep or a map starts (about 200 MB each).
MAX_WORKERS = 64
#: The most points of one map or sweep on this machine (a point of a map costs milliseconds to
#: seconds: 1e6 points are hours to days of computing; split a larger study or use a cluster).
MAX_POINTS = 1_000_000

#: The most nodes of a finite-element mesh on this machine (2 x 2^20 degrees of freedom: about
#: 2 GB and a minute to assemble; a run of it costs 2e6 dof-steps a step).
MAX_MESH_NODES = 1 << 20

COMMON = Domain("common", [
    # a friction coefficient that depends on the contact pressure (stickslip.friction.PressurePower)
    Q("pressure_exponent", "1", "exponent n of a friction coefficient that depends on the contact pressure P, "
      "mu (P / P_ref)^(-n) (n > 0: friction falls as the pressure rises)", "[-1, 1)", symbol="n",
      why="below 1 the friction force mu P grows with the pressure (at 1 it would not depend on it); from -1 a "
          "coefficient at most proportional to the pressure"),
    Q("reference_pressure", "Pa", "pressure P_ref at which a pressure-dependent friction coefficient is the law's own",
      "[1e-3, 1e12]", symbol="P_ref", why="from a millipascal to a terapascal, beyond any contact a solid bears"),
    # counters, labels and codes of results
    Q("done", "1", "point computed (1) or not yet (0)"),
    Q("seconds", "s", "wall-clock time of the computation"),
    Q("seed", "1", "seed of the random initial perturbation", "[0, 1e18]", integer=True),
    Q("case", "1", "case number"),
    Q("point", "1", "point number along the branch"),
    Q("sample", "1", "sample number"),
    Q("snapshot", "1", "snapshot number"),
    Q("node", "1", "contact node number"),
    Q("dof", "1", "degree of freedom number"),
    Q("event", "1", "event number"),
    Q("zone", "1", "zone number within one period"),
    Q("check", "1", "check number"),
    Q("start", "1", "initial condition number"),
    Q("crossing", "1", "crossing number of the Poincare section"),
    Q("k", "1", "Floquet multiplier number"),
    Q("run", "", "run label"),
    Q("kind", "", "contact state"),
    Q("variant", "", "variant of the computation"),
    Q("system", "", "system of equations"),
    Q("solution", "1", "solution number at the point"),
    Q("setting", "1", "numerical setting number"),
    Q("grid", "1", "grid number"),
    Q("mesh", "1", "mesh number"),
    Q("residual", "1", "relative residual"),
    Q("stationary", "1", "stationary limit regime (1) or not (0)"),
    Q("regime", "", "limit regime"),
    Q("multipliers", "1", "Floquet multipliers (modulus)"),
    Q("status", "", "how the computation ended"),
    Q("message", "", "what the computation says of its end"),
    Q("store", "", "the store the results are in"),
    Q("counts", "1", "points of each kind"),
    Q("axes", "", "the axes of the map: first value, last value, number of values"),
    Q("parameter", "", "the continued parameter"),
    Q("params", "", "the parameters of the computation"),
    Q("units", "", "units and meaning of every key"),
    Q("points", "1", "points along the branch", "[2, 1e5]", integer=True),
    Q("figures", "", "figure keys and titles"),
    # the settings of the shared explicit scheme (stickslip.contact) and its runs
    Q("beta2", "1", "beta2 of the explicit scheme [22] (1/2: central differences)", "[0.5, 1]",
      why="the scheme is stable and dissipative for 1/2 <= beta2 <= 1"),
    Q("courant", "1", "time step over the stable step of the explicit scheme", "(0, 1]",
      why="above 1 the explicit scheme is unstable"),
    Q("t_end", "1", "end time of the run, in the model's unit of time", "(0, 1e300]"),
    Q("transits", "1", "run length in wave transits", "(0, 1e12]",
      why="the work budget, 1e13 degree-of-freedom steps, bounds a run for its mesh"),
    Q("samples_per_transit", "1", "samples of the series per transit", "[1, 1e6]", integer=True),
    Q("snapshot_every", "1", "interval of the snapshots in transits (beyond the run: only the last)", "(0, 1e12]"),
    Q("tail", "1", "length of the dense tail in transits", "[0, 1e7]"),
    Q("volume_every", "1", "interval of the volume snapshots in transits", "(0, 1e7]"),
    Q("modes", "1", "Fourier modes tracked by the run", "[1, 1e6]", integer=True),
    Q("every", "s", "interval of the energy book", "(0, 1e300]"),
    Q("nsteps", "1", "number of steps", "[1, 1e12]", integer=True),
    Q("settle", "1", "steps left out at the start of the check", "[0, 1e12]"),
    Q("chunk", "1", "length of a run's chunk between checkpoints, in transits", "(0, 1e7]"),
    Q("min_transits", "1", "least run length in transits", "(0, 1e7]"),
    Q("max_transits", "1", "largest run length in transits", "(0, 1e7]"),
    Q("amplitude", "1", "amplitude of the initial perturbation, relative to the steady state", "[0, 100]",
      why="beyond, the start is no longer near steady sliding"),
    Q("noise", "1", "white-noise amplitude of the initial perturbation, relative to the steady state", "[0, 100]",
      why="beyond, the start is no longer near steady sliding"),
    Q("phase", "rad", "phase of the initial Fourier perturbation", "[-1e6, 1e6]"),
    Q("scaled_damping", "1", "a Rayleigh damping coefficient in the units of a scaled model", "[0, 1e30]"),
    Q("atol", "1", "absolute tolerance of the integrator (in the model's units)", "(0, 1e-3]",
      why="looser tolerances do not settle a result"),
    Q("dt", "1", "time step (in the model's units)", "(0, 1e300]"),
    Q("cdt", "1", "damping times the time step", "[0, 1e6]"),
    Q("n_theta", "1", "nodes around a ring", "[8, 4194304]", integer=True),
    Q("max_shift", "rad", "largest shift of a pattern between two snapshots", "(0, 3.141592653589793]"),
    Q("n", "1", "wave number: waves around the contact line", "[1, 4194304]", integer=True),
    # classification of a limit regime (stickslip.contact.classify)
    Q("min_fraction", "1", "least node-time fraction of a state that counts", "[0, 1)"),
    Q("min_run", "1", "least run of snapshots of a state that counts", "[1, 1e9]", integer=True),
    Q("stationarity_tol", "1", "stationarity threshold of the classification on the relative residual", "(0, 1]"),
    Q("tol", "1", "relative tolerance", "(0, 1e-3]", why="looser tolerances do not settle a result"),
    Q("rtol", "1", "relative tolerance of the integrator", "(0, 1e-3]",
      why="looser tolerances do not settle a result"),
    # sweeps and maps
    Q("workers", "1", "worker processes", f"[1, {MAX_WORKERS}]", integer=True,
      why="about 200 MB each"),
    Q("batch", "1", "points per batch of a sweep", f"[1, {MAX_POINTS}]", integer=True),
    Q("seeds", "1", "unseeded runs per case", "[1, 10000]", integer=True),
    Q("geometry_seeds", "1", "unseeded runs per case of the geometry study", "[1, 10000]", integer=True),
])
