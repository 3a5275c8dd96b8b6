# The README's two commands are `make run` and `make test`; both install what
# they need into a project-local .venv (and the console's npm packages into
# frontend/node_modules) first. `make setup` only installs.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
NODE_STAMP := frontend/node_modules/.installed-stamp

.PHONY: setup run serve test test-fast lint bench clean

$(STAMP): pyproject.toml Makefile
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	@# compile the IGA's numba kernels into their on-disk cache once, at install, rather than
	@# in the first plan (about 10 s of CPU; docs/planner.md)
	$(BIN)/python -c "from usvstation.planning.warm import warm; warm()"
	touch $(STAMP)

# The console's libraries (Leaflet, uPlot) from npm, served by the station itself
# so the console works with no internet on a ship.
$(NODE_STAMP): frontend/package.json frontend/package-lock.json
	@command -v npm >/dev/null || { echo "npm not found: install Node.js and npm" \
	  "(Debian: apt-get install nodejs npm)"; exit 1; }
	cd frontend && npm ci --no-audit --no-fund --loglevel=error
	touch $(NODE_STAMP)

setup: $(STAMP) $(NODE_STAMP)

run: setup
	$(BIN)/usv-station serve

serve: run

# Four workers (pytest-xdist), one module per worker at a time so a module's station
# fixture starts once: many tests wait on a simulated boat, so four fit on two cores.
# The tests write Python's bytecode caches (__pycache__, ignored by git) even where
# PYTHONDONTWRITEBYTECODE is set: without them every station, boat and CLI process a test
# starts compiles the package again (about 1 s of CPU each), and every worker rewrites the
# test modules' asserts again (5 s).
test: setup
	env -u PYTHONDONTWRITEBYTECODE $(BIN)/python -m compileall -q -j 0 backend
	env -u PYTHONDONTWRITEBYTECODE $(BIN)/python -m pytest -n 4 --dist loadscope

# Unit tests only (no servers, browsers, ptys, process pools or benchmarks): under a minute.
test-fast: setup
	env -u PYTHONDONTWRITEBYTECODE $(BIN)/python -m pytest tests/unit -q -n 3

lint: setup
	$(BIN)/ruff check backend tests
	$(BIN)/lint-imports --no-cache

bench: setup
	$(BIN)/usv-station bench planner --json

clean:
	rm -rf $(VENV) .pytest_cache .ruff_cache .hypothesis frontend/node_modules test-artifacts
