# propulsor — build every part in parts/*.toml into output/<name>/, test, check, bench.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PART_FILES := $(sort $(wildcard parts/*.toml))
PART_NAMES := $(patsubst parts/%.toml,%,$(PART_FILES))
PYTEST_WORKERS ?= 2
# part types that have a print kit (tests/test_print_kits.py checks this against parts._KITS)
KIT_TYPES  := noncircular_pair planetary_final_drive cam_mover road_wheel balancer polysector_gear
KIT_FILES  := $(sort $(foreach t,$(KIT_TYPES),$(shell grep -l '^type *= *"$(t)"' $(PART_FILES))))
KIT_NAMES  := $(patsubst parts/%.toml,print-%,$(KIT_FILES))
PRINTER    ?= generic

.PHONY: all install lock parts test check bench clean list print $(PART_NAMES) $(KIT_NAMES)

all: parts

install: $(STAMP)

# constraints.txt pins every package to the version the outputs were proven with; `make lock`
# renews it on purpose (a fresh venv with the newest versions allowed by pyproject.toml)
$(STAMP): pyproject.toml constraints.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q -c constraints.txt pip
	$(BIN)/python -m pip install -q -c constraints.txt -e '.[test]'
	touch $@

lock:
	rm -rf .venv-lock && $(PYTHON) -m venv .venv-lock
	.venv-lock/bin/python -m pip install -q --upgrade pip && .venv-lock/bin/python -m pip install -q -e '.[test]'
	.venv-lock/bin/python -m pip freeze --all --exclude-editable > constraints.txt
	rm -rf .venv-lock

parts: $(PART_NAMES)

$(PART_NAMES): %: parts/%.toml $(STAMP)
	$(BIN)/propulsor build $< --out output/$@

print: $(KIT_NAMES)

$(KIT_NAMES): print-%: parts/%.toml $(STAMP)
	$(BIN)/propulsor print $< --printer $(PRINTER) --out output/$*_kit

list: $(STAMP)
	$(BIN)/propulsor list

test: $(STAMP)
	$(BIN)/python -m pytest -q -n $(PYTEST_WORKERS) --dist loadgroup -m "not sweep" tests

check: $(STAMP)
	$(BIN)/propulsor check output/
	$(BIN)/python -m pytest -q -m sweep tests

bench: $(STAMP)
	$(BIN)/python bench/run.py

clean:
	rm -rf output/*/ .pytest_cache .hypothesis .benchmarks
