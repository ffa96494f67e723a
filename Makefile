# Two commands matter: `make demo` and `make test`. Both set up what they need.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
RUNTIME := $(VENV)/.ready-runtime
DEV := $(VENV)/.ready-dev
PIP := $(BIN)/python -m pip install -q --disable-pip-version-check
# pytest on every core (pytest-xdist). Each test file runs on one worker, so that a module's costly fixture
# (the compiled LaTeX documents) is built once. (--dist loadgroup would be finer, but pytest-xdist 3.8's groups
# do not take under pytest 9.2: it renames item._nodeid, which pytest 9 no longer reads.)
JOBS ?= auto
PYTEST := $(BIN)/python -m pytest -n $(JOBS) --dist loadfile

# The fast lane for the edit-test loop (`make check`, under a minute on two cores): no notebooks, browser,
# pdflatex, pip, fuzzing or closed-form solutions of real robots; the seconds-long tests are listed in tests/conftest.py.
.PHONY: demo test check install tex browser node-packages bench lint notebooks web clean

# The demo needs only what dhsym itself imports; the tests add pytest, jupyter, ruff and friends.
$(RUNTIME): pyproject.toml requirements.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(PIP) -r requirements.txt
	$(PIP) --no-deps -e .
	$(BIN)/python -m compileall -q dhsym  # bytecode even where PYTHONDONTWRITEBYTECODE keeps Python from writing it
	touch $(RUNTIME)

$(DEV): $(RUNTIME) requirements-dev.txt
	$(PIP) -r requirements-dev.txt
	touch $(DEV)

install: $(DEV)

tex:
	@bash scripts/ensure-tex.sh

# Chromium for the notebook-page test; MathJax (npm) typesets the notebook pages.
browser:
	@bash scripts/ensure-browser.sh

node-packages:
	@bash scripts/ensure-node-packages.sh

demo: $(RUNTIME)
	$(BIN)/dhsym fk puma560

test: install tex browser node-packages
	$(BIN)/ruff check dhsym tests benchmarks
	$(PYTEST)

check: install
	$(BIN)/ruff check dhsym tests benchmarks
	HYPOTHESIS_PROFILE=quick $(PYTEST) -m "not slow" -x

bench: install web browser
	$(BIN)/python benchmarks/simplify_speed.py
	$(BIN)/python benchmarks/velocity_speed.py
	$(BIN)/python benchmarks/geometry_speed.py
	$(BIN)/python benchmarks/ik_speed.py
	$(BIN)/python benchmarks/ik_peers.py
	$(BIN)/python benchmarks/dynamics_speed.py
	$(BIN)/python benchmarks/ik_numeric_speed.py
	$(BIN)/python benchmarks/startup.py
	$(BIN)/python benchmarks/web_speed.py

notebooks: install node-packages
	bash scripts/export-notebooks.sh

# The browser page: a folder of static files (Pyodide, SymPy and dhsym as local wheels, MathJax), from the
# registries only (docs/web.md). Serve it with `python3 -m http.server -d build/web`.
web: $(RUNTIME) node-packages
	$(BIN)/python scripts/build_web.py build/web

lint: install
	$(BIN)/ruff check dhsym tests benchmarks

clean:
	rm -rf $(VENV) build node_modules .pytest_cache .hypothesis
