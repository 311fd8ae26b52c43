# propulsor — build every part in parts/*.toml into output/<name>/, test, check, bench.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PART_FILES := $(sort $(wildcard parts/*.toml))
# make names a part file as it is, in rules and in the shell: a part file whose name holds anything but
# letters (any alphabet), digits and . _ - + stops make before it reads one (`propulsor build` builds it)
BAD_PART_FILES := $(shell LC_ALL=C find parts -maxdepth 1 -name '*.toml' ! -name '.*' 2>/dev/null | \
	LC_ALL=C grep -v '^parts/\([-A-Za-z0-9._+]\|[^ -~[:cntrl:]]\)*\.toml$$' | LC_ALL=C tr -c '[:print:]\n' '?' | \
	sed "s/.*/'&'/")
ifneq ($(BAD_PART_FILES),)
$(error $(BAD_PART_FILES): make cannot name a part file with characters other than letters, digits, . _ - +; rename it, or run propulsor build on it)
endif
PART_NAMES := $(patsubst parts/%.toml,%,$(PART_FILES))
OUT        := output
# a part's build is out of date when its part file, a file it names (the depfile the build writes),
# the package's source or the installed versions (the venv stamp) are newer than its manifest
SOURCES    := $(sort $(shell find src -type f \( -name '*.py' -o -name '*.toml' \) 2>/dev/null))
MANIFESTS  := $(patsubst %,$(OUT)/%/manifest.json,$(PART_NAMES))
DEPS       := $(OUT)/.deps
PYTEST_WORKERS ?= 2
# part types that have a print kit (tests/test_print_kits.py checks this against parts._KITS)
KIT_TYPES  := noncircular_pair planetary_final_drive cam_mover road_wheel balancer polysector_gear
KIT_FILES  := $(sort $(foreach t,$(KIT_TYPES),$(shell grep -l '^type *= *"$(t)"' $(PART_FILES))))
KIT_NAMES  := $(patsubst parts/%.toml,print-%,$(KIT_FILES))
KIT_MANIFESTS := $(patsubst parts/%.toml,$(OUT)/%_kit/manifest.json,$(KIT_FILES))
PRINTER    ?= generic

.PHONY: all install lock parts gallery test check bench mutation mutation-handmade clean list print docs viewer-lib validate-glb $(PART_NAMES) $(KIT_NAMES)

all: parts $(OUT)/index.html

install: $(STAMP)

# constraints.txt pins every package to the version the outputs were proven with; `make lock`
# renews it on purpose (a fresh venv with the newest versions allowed by pyproject.toml)
$(STAMP): pyproject.toml constraints.txt
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q -c constraints.txt pip
	$(BIN)/python -m pip install -q -c constraints.txt -e '.[test,docs]'
	@# the package's modules compiled to bytecode once, as pip compiles those of a package it installs (not those of an
	@# editable install): where PYTHONDONTWRITEBYTECODE is set, every process compiled every module it imported again
	$(BIN)/python -m compileall -q src
	@echo "compiling the numeric kernels once (about 30 s)"
	$(BIN)/python -c 'from propulsor.checks.kernels import warm; warm()'
	touch $@

lock:
	rm -rf .venv-lock && $(PYTHON) -m venv .venv-lock
	.venv-lock/bin/python -m pip install -q --upgrade pip && .venv-lock/bin/python -m pip install -q -e '.[test,docs]'
	.venv-lock/bin/python -m pip freeze --all --exclude-editable > constraints.txt
	rm -rf .venv-lock

parts: $(OUT)/.built

# An out-of-date part is queued; then one process builds the queue (the imports are paid once, and
# the builds run side by side, keeping the machine's cores busy).  $(OUT)/.built is newer than every
# manifest after a complete run, so a second `make` runs no recipe at all.  The build's recipe is
# marked `+` so that under `make -jN` it gets make's jobserver: its builds and their workers take
# make's tokens, and never run more processes than make allows (nor than the cores).  `+` also runs a
# recipe under `make -n`, hence the guard: a dry run only names the queue.
QUEUE := $(OUT)/.build-queue
DRY_RUN = $(findstring n,$(firstword -$(MAKEFLAGS)))
FLUSH = if [ -s $(QUEUE) ]; then q=$$(sort -u $(QUEUE)); \
	$(if $(DRY_RUN),printf "would build: %s\n" "$$q";,rm -f $(QUEUE); $(BIN)/propulsor build $$q --out-dir $(OUT) --depfile-dir $(DEPS);) fi

# the files each build read, written by the builds themselves (escaped for make; each with an empty rule,
# so that a file deleted since rebuilds what read it): the depfiles of the part files there are (that of
# a part file deleted or renamed is not read)
PROPULSOR_READ :=
-include $(wildcard $(patsubst parts/%.toml,$(DEPS)/%.mk,$(PART_FILES)) \
	$(patsubst parts/%.toml,$(DEPS)/%_kit.mk,$(KIT_FILES)))

# .built also depends on what the manifests depend on: a manifest whose recipe only queued its part keeps
# its time stamp, so make would not remake .built for it (GNU make remakes a target for a prerequisite
# that is newer, not for one whose recipe ran); every file a build read is added to PROPULSOR_READ by its
# depfile
$(OUT)/.built: $(MANIFESTS) $(PART_FILES) $(SOURCES) $(STAMP) $(PROPULSOR_READ)
	+@$(FLUSH)
	@touch $@

# the gallery of everything built in output/.  The builds rewrite a gallery propulsor wrote (and ./output's) when
# their output is in place (`propulsor build` of several part files once, after the last): when the builds' run
# (.built) is all that is newer than a page of ours, the page is current and only its time stamp is renewed (writing
# the page again, some 40 MB with every part's 3D model, took half a second)
# (GALLERY_MARK: export/gallery.py GENERATOR, the mark its is_ours reads; tests/test_make_targets.py holds them equal)
GALLERY_MARK := <meta name="generator" content="propulsor">
$(OUT)/index.html: $(OUT)/.built $(SOURCES) $(wildcard src/propulsor/export/web/*) $(STAMP)
	@if [ "$?" = "$(OUT)/.built" ] && [ -f $@ ] && [ ! -L $@ ] && head -c 4096 $@ | grep -qF '$(GALLERY_MARK)'; \
	then touch $@; else echo "$(BIN)/propulsor gallery $(OUT) -q"; $(BIN)/propulsor gallery $(OUT) -q; fi

gallery: $(STAMP)
	$(BIN)/propulsor gallery $(OUT)

# `make <name>`: that part, when out of date
$(PART_NAMES): %: $(OUT)/%/manifest.json
	+@$(FLUSH)

$(OUT)/%/manifest.json: parts/%.toml $(SOURCES) $(STAMP)
	@mkdir -p $(OUT) && echo $< >> $(QUEUE)

print: $(KIT_MANIFESTS)

$(KIT_NAMES): print-%: $(OUT)/%_kit/manifest.json

$(OUT)/%_kit/manifest.json: parts/%.toml $(SOURCES) $(STAMP)
	$(BIN)/propulsor print $< --printer $(PRINTER) --out $(OUT)/$*_kit --depfile $(DEPS)/$*_kit.mk

# the 3D viewer's library, vendored: three.js bundled (web/bundle.mjs, esbuild) into one script the pages
# inline, so that they work opened from disk with nothing fetched; its version is pinned in web/package.json
# and web/package-lock.json (change it there, then `make viewer-lib` and commit the three files it writes)
WEB_STAMP := web/node_modules/.package-lock.json
$(WEB_STAMP): web/package.json web/package-lock.json
	cd web && npm ci --no-audit --no-fund
	touch $@

viewer-lib: $(WEB_STAMP)
	cd web && node bundle.mjs

# the Khronos glTF validator (npm's gltf-validator) over every GLB in output/: 0 errors and 0 warnings
validate-glb: $(WEB_STAMP)
	node web/validate_glb.mjs $(OUT)

list: $(STAMP)
	$(BIN)/propulsor list

# the layer contracts first (import-linter, [tool.importlinter] in pyproject.toml), then the tests
test: $(STAMP)
	$(BIN)/lint-imports pyproject.toml
	$(BIN)/python -m pytest -q -n $(PYTEST_WORKERS) --dist loadfile -m "not sweep" --durations=30 tests

# the user guide (mkdocs-material, docs/ -> site/, warnings are errors): the API reference from the docstrings
# first (pdoc into docs/api/, warnings as errors), then the site, whose reference pages docs/hooks.py generates
# from the code (docs/gen_reference.py); the docs extra is installed from constraints.txt when missing
docs: $(STAMP)
	$(BIN)/python -c "import mkdocs, material" 2>/dev/null || $(BIN)/python -m pip install -q -c constraints.txt -e '.[docs]'
	rm -rf docs/api
	$(BIN)/python -W error -m pdoc propulsor.api propulsor.errors propulsor.check -o docs/api
	NO_MKDOCS_2_WARNING=1 $(BIN)/python -m mkdocs build --strict --clean

# the print kits' sweep (every part file on every printer profile, one test a part file) runs its part files
# side by side
check: $(STAMP) $(WEB_STAMP)
	$(BIN)/propulsor check output/
	node web/validate_glb.mjs $(OUT)
	$(BIN)/python -m pytest -q -m sweep tests --ignore=tests/test_print_kits_printers.py
	$(BIN)/python -m pytest -q -n $(PYTEST_WORKERS) --dist load -m sweep tests/test_print_kits_printers.py

bench: $(STAMP)
	$(BIN)/python bench/run.py

# mutation testing (mutmut) of the modules whose numbers a user trusts, each against the tests that reach it, with
# a score per module (mutation/targets.toml, mutation/equivalent.toml); MODULE=<target or module file> runs one.
# Not in `make test`: all targets take hours on two cores (mutation/README.md gives the times)
mutation: $(STAMP)
	$(BIN)/python mutation/run.py $(if $(MODULE),--module $(MODULE))

# the hand-made one-line mutants of issue 36 (mutation/handmade.toml, written without reading the tests), each against
# the test files that name its module; the score per module group (mutation/README.md, «Hand-made mutants»; ~15-25 min
# a round; ROUND=1 or ROUND=2 runs one round, both by default)
mutation-handmade: $(STAMP)
	$(BIN)/python mutation/handmade.py $(if $(ROUND),--round $(ROUND))

clean:
	rm -rf $(OUT)/*/ $(DEPS) $(OUT)/.built $(QUEUE) .pytest_cache .hypothesis .benchmarks site
