"""The package's exceptions survive the trip back from a worker process (pickling)."""

import pickle

from stickslip.errors import NoSolutionError, ParameterError


def test_parameter_error_pickles_with_its_fields():
    err = pickle.loads(pickle.dumps(ParameterError("--x", "belt_speed=0:1:3", "values > 0")))
    assert (err.name, err.value, err.allowed) == ("--x", "belt_speed=0:1:3", "values > 0")
    assert str(err) == "invalid --x = 'belt_speed=0:1:3': must be values > 0"


def test_no_solution_error_pickles():
    assert str(pickle.loads(pickle.dumps(NoSolutionError("no limit cycle")))) == "no limit cycle"
