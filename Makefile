# propulsor — build every part in parts/*.toml into output/<name>/, test, check, bench.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PART_FILES := $(sort $(wildcard parts/*.toml))
PART_NAMES := $(patsubst parts/%.toml,%,$(PART_FILES))
PYTEST_WORKERS ?= 2
# part types that have a print kit (tests/test_print_kits.py checks this against parts._KITS)
KIT_TYPES  := noncircular_pair planetary_final_drive
KIT_FILES  := $(sort $(foreach t,$(KIT_TYPES),$(shell grep -l '^type *= *"$(t)"' $(PART_FILES))))
KIT_NAMES  := $(patsubst parts/%.toml,print-%,$(KIT_FILES))
PRINTER    ?= generic

.PHONY: all install parts test check bench clean list print $(PART_NAMES) $(KIT_NAMES)

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

print: $(KIT_NAMES)

$(KIT_NAMES): print-%: parts/%.toml $(STAMP)
	$(BIN)/propulsor print $< --printer $(PRINTER) --out output/$*_kit

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
