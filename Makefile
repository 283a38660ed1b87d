# freestand: the two set-up commands are `make demo` and `make test`.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
DOCS_STAMP := $(VENV)/.installed-docs

.PHONY: install demo test lint format bench clean docs docs-test

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[dev]"
	touch $(STAMP)

install: $(STAMP)

demo: $(STAMP)
	$(BIN)/freestand screen examples/crane.toml
	$(BIN)/freestand report examples/crane.toml -o build/crane-report.html
	@echo "screening report: $(CURDIR)/build/crane-report.html"

# The compiled kernels first, once, in two processes (tests/compile_kernels.py): the test
# workers then load them from numba's cache instead of each compiling all of them.
test: $(STAMP)
	$(BIN)/python tests/compile_kernels.py
	$(BIN)/python -m pytest -q -n auto --durations=25

LINTED := src tests benchmarks examples docs/conf.py docs/_ext

lint: $(STAMP)
	$(BIN)/ruff check $(LINTED)
	$(BIN)/ruff format --check $(LINTED)

format: $(STAMP)
	$(BIN)/ruff format $(LINTED)
	$(BIN)/ruff check --fix $(LINTED)

# The documentation site: user guide, API and model-file reference, executed gallery.
# Warnings are errors; the site opens offline from build/docs/index.html.
$(DOCS_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -e ".[dev,docs]"
	touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)
	MPLBACKEND=Agg $(BIN)/sphinx-build -W --keep-going -q -b html docs build/docs
	@echo "documentation: $(CURDIR)/build/docs/index.html"

# The built site rendered in headless Chromium (tests/test_docs_browser.py).
docs-test: docs
	FREESTAND_DOCS=$(CURDIR)/build/docs $(BIN)/python -m pytest -q tests/test_docs_browser.py

bench: $(STAMP)
	$(BIN)/python -m pip install --quiet -e ".[dev,bench]"
	$(BIN)/python benchmarks/run.py

clean:
	rm -rf $(VENV) build dist .pytest_cache .hypothesis
	rm -rf docs/generated docs/gallery docs/model-file.md docs/sg_execution_times.rst
