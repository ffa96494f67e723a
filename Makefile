# Two commands matter: `make demo` and `make test`. Both set up what they need.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
READY := $(VENV)/.ready

.PHONY: demo test install tex bench lint notebooks clean

$(READY): pyproject.toml requirements.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --disable-pip-version-check -r requirements.txt
	$(BIN)/python -m pip install -q --disable-pip-version-check --no-deps -e .
	touch $(READY)

install: $(READY)

tex:
	@bash scripts/ensure-tex.sh

demo: install
	$(BIN)/dhsym fk puma560

test: install tex
	$(BIN)/python -m pytest

bench: install
	$(BIN)/python benchmarks/simplify_speed.py
	$(BIN)/python benchmarks/geometry_speed.py

notebooks: install
	bash scripts/export-notebooks.sh

lint: install
	$(BIN)/ruff check dhsym tests benchmarks

clean:
	rm -rf $(VENV) build .pytest_cache .hypothesis
