# Two entry points (see README): `make reproduce` and `make test`.
# Each builds the virtual environment on first use; later runs reuse it.
PYTHON ?= python3
# the tests and the docs start hundreds of Python processes that import the package (and pytest
# rewrites every test module): with bytecode caching off (PYTHONDONTWRITEBYTECODE, set on some
# machines) each one compiles them again, 6 s of every test worker's collection
unexport PYTHONDONTWRITEBYTECODE
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.stickslip-installed
TEST_STAMP := $(VENV)/.stickslip-test-installed
OUT    ?= results

.PHONY: reproduce reproduce-quick test test-slow test-all test-deep bench docs clean

# the package and its dependencies: all that `make reproduce` needs
$(STAMP): pyproject.toml
	@$(PYTHON) -c 'import sys; assert sys.version_info >= (3, 11), "Python >= 3.11 is required"'
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e .
	touch $(STAMP)

# the tests' extra, and the numba kernels compiled once into their cache on disk (about 20 s), not
# by the first test workers that meet them, both at once (src/stickslip/precompile.py); a
# reproduction's figures compile what they meet themselves, one worker each
$(TEST_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -e '.[test]'
	$(BIN)/python -m stickslip.precompile
	touch $(TEST_STAMP)

reproduce: $(STAMP)
	$(BIN)/stickslip reproduce --out $(OUT) $(ARGS)

reproduce-quick: $(STAMP)
	$(BIN)/stickslip reproduce --out $(OUT) --quick $(ARGS)

test: $(TEST_STAMP)
	$(BIN)/python -m pytest -q -n 2 --dist worksteal -m "not slow" $(ARGS)

test-slow: $(TEST_STAMP)
	$(BIN)/python -m pytest -q -n 2 --dist worksteal -m "slow and not deep" $(ARGS)

test-all: $(TEST_STAMP)
	$(BIN)/python -m pytest -q -n 2 --dist worksteal $(ARGS)

# every property test (Hypothesis), the slow ones too, with ten times the examples, drawn afresh,
# and the tests of minutes each that CI leaves out (marked deep): before an issue is resolved
# (tests/conftest.py: the profiles)
test-deep: $(TEST_STAMP)
	$(BIN)/python -m pytest -q -n 2 --dist worksteal -m "hypothesis or deep" --hypothesis-profile deep $(ARGS)

bench: $(TEST_STAMP)
	for b in $(filter-out benchmarks/timing.py,$(wildcard benchmarks/*.py)); do echo "== $$b"; $(BIN)/python $$b || exit 1; done

# docs/errata.md, docs/parameters.md and docs/cli/ regenerated from the package, then the HTML (Markdown docs, the
# notebooks executed, the gallery's scripts run, the API reference from the docstrings) in build/docs/html; a
# warning fails the build
DOCS_STAMP := $(VENV)/.stickslip-docs-installed

$(DOCS_STAMP): $(TEST_STAMP)
	$(BIN)/python -m pip install --quiet -e '.[test,docs]'
	touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)
	$(BIN)/python -m stickslip.errata > docs/errata.md
	$(BIN)/python -m stickslip.quantities > docs/parameters.md
	$(BIN)/python -m stickslip.cli.reference docs/cli
	$(BIN)/python -m sphinx -M html docs build/docs -W --keep-going -q
	$(BIN)/python docs/check_html.py build/docs/html

clean:
	rm -rf $(VENV) results .pytest_cache
