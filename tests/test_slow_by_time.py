"""The list of the fast set's slow tests names tests that exist (a renamed test would drop out of it and back
into ``make test`` unseen)."""

import ast

from tests.slow_by_time import LIST, ROOT, listed, node_id


def test_every_listed_test_is_a_test_function_of_its_file():
    missing = []
    for node in sorted(listed()):
        path, *names = node.split("::")
        file = ROOT / path
        if not file.is_file():
            missing.append(node)
            continue
        defined = {n.name for n in ast.walk(ast.parse(file.read_text())) if isinstance(n, ast.FunctionDef)}
        if names[-1].split("[")[0] not in defined:
            missing.append(node)
    assert not missing, f"{LIST.name} lists tests that are not there: {missing}"


def test_a_junit_class_name_becomes_the_node_id_pytest_gives():
    assert node_id("tests.sbim.test_cli_fault", "test_x[1-2]") == "tests/sbim/test_cli_fault.py::test_x[1-2]"
    assert node_id("tests.test_report", "test_y") == "tests/test_report.py::test_y"
