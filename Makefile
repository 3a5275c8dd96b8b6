# The README's two commands are `make run` and `make test`; both install what
# they need into a project-local .venv first. `make setup` only installs.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp

.PHONY: setup run test lint bench clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	touch $(STAMP)

setup: $(STAMP)

run: setup
	$(BIN)/usv-station serve

test: setup
	$(BIN)/python -m pytest

lint: setup
	$(BIN)/ruff check backend tests

bench: setup
	$(BIN)/usv-station bench planner --json

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache .hypothesis
