# propulsor — build every part in parts/*.toml into output/<name>/, test, check, bench.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PART_FILES := $(sort $(wildcard parts/*.toml))
PART_NAMES := $(patsubst parts/%.toml,%,$(PART_FILES))
PYTEST_WORKERS ?= 2

.PHONY: all install parts test check bench clean list $(PART_NAMES)

all: parts

install: $(STAMP)

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[test]'
	touch $@

parts: $(PART_NAMES)

$(PART_NAMES): %: parts/%.toml $(STAMP)
	$(BIN)/propulsor build $< --out output/$@

list: $(STAMP)
	$(BIN)/propulsor list

test: $(STAMP)
	$(BIN)/python -m pytest -q -n $(PYTEST_WORKERS) -m "not sweep" tests

check: $(STAMP)
	$(BIN)/propulsor check output/
	$(BIN)/python -m pytest -q -m sweep tests

bench: $(STAMP)
	$(BIN)/python bench/run.py

clean:
	rm -rf output/*/ .pytest_cache .hypothesis .benchmarks
