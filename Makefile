# Reproducible environment + workflow entry points.
#
#   make venv       create .venv from environment.lock (hash-checked, Python 3.11 only; uv installs it), then
#                   install this project editable into it (--no-deps): .venv/bin/inertial-repro
#   make test       run the test suite            (PYTEST_ARGS="-k foo -x" to pass options;
#                   TEST_WORKERS=2 pytest-xdist workers by default, 0 for one process);
#                   first installs the system tools the report tests drive (system-deps)
#   make reproduce  run the Snakemake workflow    (CORES=2 by default), after warm-kernels
#   make warm-kernels  the papers' set-up work (pipeline/warm_up.py): altimeter_attitude's numba
#                   kernels compiled into numba's cache, so that the workflow's jobs load them
#                   (nothing to do when the cache is warm); run by `make reproduce` and `make test`
#   make reproduce-slurm  the same workflow on a SLURM cluster (profiles/slurm/: the executor
#                   plugin submits the steps with sbatch; run it from a login node)
#   make lint       ruff check + ruff format --check, snakefmt --check, snakemake --lint
#   make system-deps  Debian's chromium (headless browser) and poppler-utils (pdftoppm), if missing
#   make bench      benchmarks (altimeter_attitude filters vs filterpy; a full `make reproduce`
#                   from nothing in a copy of the checkout, its steps, a no-op), on demand
#   make lock       regenerate environment.lock from requirements.in
#   make clean      remove workflow outputs (results/, .snakemake/); keeps .venv

SHELL := /bin/bash

PYTHON      ?= python3
REQUIRED_PY := 3.11
VENV        := .venv
STAMP       := $(VENV)/.stamp
# The project itself, installed editable (its console script) after the lock's packages.
PROJECT_STAMP := $(VENV)/.project-stamp
CORES       ?= 2
PYTEST_ARGS ?=
# pytest-xdist workers; each test file runs whole in one worker (its module fixtures once)
TEST_WORKERS ?= 2

# Build backend installed (hash-checked, from the lock) before everything else, so the one
# sdist-only dependency can be built with --no-build-isolation from pinned, hashed files;
# uv (also from the lock) then installs the lock.
BUILD_PKGS := setuptools wheel packaging

# Lock tool: uv in a throwaway venv outside the project (never in .venv).
LOCK_TOOL_VENV ?= /tmp/inertial-repro-lock-tool
UV_VERSION     ?= 0.13.9  # keep equal to the uv pin of requirements.in (make venv installs that one)
UV             := $(LOCK_TOOL_VENV)/bin/uv
# Keep identical to the command recorded in the header of environment.lock.
LOCK_ARGS := pip compile --generate-hashes --python-version 3.11 \
	--python-platform x86_64-unknown-linux-gnu requirements.in -o environment.lock

# System tools of the report tests: Debian's chromium loads reports/reproduction.html headless,
# poppler-utils renders reports/reproduction.pdf. Installed with apt-get when missing (as root,
# or with password-less sudo); otherwise those tests are skipped with a warning here, unless
# REQUIRE_SYSTEM_DEPS=1 (CI), which makes a missing tool an error.
SYSTEM_TOOLS := /usr/bin/chromium /usr/bin/pdftoppm /usr/bin/pdftotext /usr/bin/pdfinfo
SYSTEM_PKGS  := chromium poppler-utils
REQUIRE_SYSTEM_DEPS ?= 0

.PHONY: venv warm-kernels reproduce reproduce-locked reproduce-slurm check-slurm workflow snakemake-report test lint bench lock clean check-python system-deps

venv: $(PROJECT_STAMP)

check-python:
	@found="$$($(PYTHON) -c 'import platform; print(platform.python_version())' 2>/dev/null)"; \
	if [ -z "$$found" ]; then \
		echo "error: '$(PYTHON)' not found or not runnable; Python $(REQUIRED_PY).x is required" >&2; \
		exit 1; \
	fi; \
	case "$$found" in \
		$(REQUIRED_PY).*) ;; \
		*) echo "error: '$(PYTHON)' is Python $$found, but Python $(REQUIRED_PY).x is required" \
			"(environment.lock is pinned for $(REQUIRED_PY))" >&2; \
		   exit 1 ;; \
	esac

# pip installs the lock's uv and build backend (hash-checked, no dependencies); uv installs the
# rest, hash-checked, in parallel, and compiles the bytecode (what pip does, so the first
# `make reproduce` does not pay for it): measured 33 s wall / 54 CPU-s instead of pip's
# 98 s / 94 CPU-s (cold caches). --system-certs: the machine's CA store, as pip uses.
$(STAMP): environment.lock
	@$(MAKE) --no-print-directory check-python
	rm -rf $(VENV)
	$(PYTHON) -m venv $(VENV)
	awk -v pkgs="$(BUILD_PKGS) uv" \
		'BEGIN { n = split(pkgs, a, " "); for (i = 1; i <= n; i++) want[a[i]] = 1 } \
		 /^[A-Za-z0-9]/ { split($$0, f, "=="); keep = (f[1] in want) } \
		 keep' environment.lock > $(VENV)/build-requirements.txt
	$(VENV)/bin/pip install --no-input --require-hashes --no-deps -r $(VENV)/build-requirements.txt
	$(VENV)/bin/uv pip install --quiet --python $(VENV)/bin/python --require-hashes \
		--no-build-isolation --compile-bytecode --link-mode copy --system-certs -r environment.lock
	touch $@

# Editable, so the source tree is what runs; --no-deps so that only the lock's pins are used
# (the project declares none); --no-build-isolation so that the build backend is the lock's
# hash-checked setuptools, not a fresh download. Redone when pyproject.toml changes (the console
# scripts are declared there), without rebuilding the environment.
$(PROJECT_STAMP): $(STAMP) pyproject.toml
	$(VENV)/bin/pip install --no-input --no-deps --no-build-isolation --editable .
	touch $@

# One `make reproduce` at a time per checkout (flock); inside it, a Snakemake lock left by a
# killed run is stale and is released, and the outputs a killed run left incomplete are rerun.
# Snakemake with one fix to its scheduler loop (pipeline/run_snakemake.py: ~20 CPU-s of a full run)
SNAKEMAKE_RUN := PYTHONPATH=$(CURDIR) $(VENV)/bin/python -m pipeline.run_snakemake

# How `workflow` runs the jobs: here, on CORES cores; `make reproduce-slurm` passes the profile.
# Snakemake's greedy scheduler, not its default MILP one: the jobs' priorities (pipeline/
# job_priority.py) decide the order either way, and the MILP one solved a problem with an
# external solver (CBC, a subprocess) at each of ~40 selections, ~0.4 CPU-s a full run.
WORKFLOW_ARGS ?= --cores $(CORES) --scheduler greedy
# CONFIG=my.yaml: your settings over config/config.yaml (Snakemake's --configfile), checked
# strictly by pipeline/check_config.py before Snakemake reads them
CONFIG ?=
CONFIG_ARGS := $(if $(strip $(CONFIG)),--configfile $(CONFIG))
SLURM_PROFILE ?= profiles/slurm

# The papers' set-up work before a workflow (pipeline/warm_up.py calls each plug-in's warm_up):
# altimeter_attitude compiles its numba kernels (~11 CPU-s on an empty cache, else paid by the
# workflow's first Monte Carlo jobs while the others wait on the cache's lock). Phony, no stamp
# here: each warm-up keeps its own (numba's in its cache, removed by `make clean`), so this costs
# ~0.1 CPU-s when done; a failure is a warning (the jobs do that work then).
warm-kernels: $(PROJECT_STAMP)
	@PYTHONPATH=$(CURDIR) $(VENV)/bin/python -m pipeline.warm_up

reproduce: $(PROJECT_STAMP)
	@mkdir -p .snakemake
	@flock -n -E 75 .snakemake/make-reproduce.lock $(MAKE) --no-print-directory reproduce-locked \
		WORKFLOW_ARGS="$(WORKFLOW_ARGS)"; \
	status=$$?; if [ $$status -eq 75 ]; then \
		echo "error: another 'make reproduce' is running in $(CURDIR); wait for it to finish" >&2; \
	fi; exit $$status

# What `make reproduce` runs under its lock: the kernels' warm-up, then the workflow.
reproduce-locked: warm-kernels
	@$(MAKE) --no-print-directory workflow WORKFLOW_ARGS="$(WORKFLOW_ARGS)"

# The same workflow and the same bytes, its steps submitted with sbatch (the short ones run here,
# on the login node: localrules). The clone and .venv must be on a filesystem the nodes share.
reproduce-slurm: $(PROJECT_STAMP) check-slurm
	@$(MAKE) --no-print-directory reproduce WORKFLOW_ARGS="--profile $(SLURM_PROFILE)"

check-slurm:
	@missing=""; \
	command -v sbatch >/dev/null 2>&1 || missing="$$missing\n  sbatch, SLURM's client (run this on the cluster's login node; on Debian: apt-get install slurm-client; a one-node test cluster: .ci/slurm up)"; \
	command -v squeue >/dev/null 2>&1 || missing="$$missing\n  squeue, SLURM's client (the status command of $(SLURM_PROFILE)/config.yaml)"; \
	$(VENV)/bin/python -c 'import snakemake_executor_plugin_slurm, snakemake_executor_plugin_slurm_jobstep' \
		2>/dev/null || missing="$$missing\n  snakemake-executor-plugin-slurm(-jobstep) in $(VENV) (both are in environment.lock: rm -rf $(VENV) && make venv)"; \
	[ -f $(SLURM_PROFILE)/config.yaml ] || missing="$$missing\n  the profile $(SLURM_PROFILE)/config.yaml"; \
	if [ -n "$$missing" ]; then printf "error: make reproduce-slurm needs:$$missing\n" >&2; exit 1; fi

workflow:
	@if [ -n "$$(ls -A .snakemake/locks 2>/dev/null)" ]; then \
		echo "a Snakemake lock from an interrupted run is left: releasing it"; \
		$(SNAKEMAKE_RUN) --unlock --quiet; \
	fi
	$(if $(strip $(CONFIG)),PYTHONPATH=$(CURDIR) $(VENV)/bin/python -m pipeline.check_config $(CONFIG))
	@tmp="$(REPORT_TMP)"; report=""; \
	if $(REPORT_STALE); then \
		report="--report $(CURDIR)/$$tmp --report-after-run"; mkdir -p $(dir $(SNAKEMAKE_REPORT)); \
	fi; \
	trap 'rm -f "$$tmp"' EXIT; \
	cmd="$(SNAKEMAKE_RUN) $(WORKFLOW_ARGS) $(CONFIG_ARGS) --rerun-incomplete \
		--rerun-triggers mtime params input code software-env --printshellcmds $$report"; \
	echo "$$cmd"; eval "$$cmd" || exit $$?; \
	if [ -n "$$report" ] && [ -f "$$tmp" ]; then mv -f "$$tmp" $(SNAKEMAKE_REPORT); fi
	@$(MAKE) --no-print-directory snakemake-report

# Snakemake's HTML report (~9 s of CPU, 27 MB) only when something it shows is newer than it:
# a tagged output or log under results/ or reports/, its captions, the rules and scripts it
# lists, the config, or the run metadata (runtimes) a job writes. Written to a temporary file
# in reports/ and renamed over the old one, so an interrupted report leaves the old one whole.
# With CONFIG= it is always rebuilt (the config it shows may differ from the last run's).
# When it is already stale before the run (a fresh clone, after `make clean`), the run itself
# writes it at its end (--report-after-run: no second start of Snakemake, ~3 CPU-s and as many
# seconds at the end of a full run); else it is built after the run if the run changed it.
SNAKEMAKE_REPORT := reports/snakemake.html
REPORT_SOURCES   := Snakefile config pipeline/rules pipeline/scripts results reports \
	.snakemake/metadata

# (shell) whether the report is missing or older than something it shows
REPORT_STALE := { [ ! -f $(SNAKEMAKE_REPORT) ] || [ -n "$(strip $(CONFIG))" ] || \
	[ -n "$$(find $(REPORT_SOURCES) -type f -newer $(SNAKEMAKE_REPORT) ! -path $(SNAKEMAKE_REPORT) \
		! -name '.snakemake-report.*' -print -quit 2>/dev/null)" ]; }
REPORT_TMP := $(dir $(SNAKEMAKE_REPORT)).snakemake-report.$$$$.html

snakemake-report:
	@if ! $(REPORT_STALE); then \
		echo "$(SNAKEMAKE_REPORT) is up to date"; exit 0; \
	fi; \
	mkdir -p $(dir $(SNAKEMAKE_REPORT)); \
	tmp="$(REPORT_TMP)"; \
	trap 'rm -f "$$tmp"' EXIT; \
	$(SNAKEMAKE_RUN) $(CONFIG_ARGS) --report $(CURDIR)/$$tmp && mv -f "$$tmp" $(SNAKEMAKE_REPORT)

system-deps:
	@missing=""; for t in $(SYSTEM_TOOLS); do [ -x "$$t" ] || missing="$$missing $$t"; done; \
	if [ -z "$$missing" ]; then exit 0; fi; \
	if [ "$$(id -u)" = 0 ]; then sudo=""; \
	elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then sudo="sudo -n"; \
	else sudo="none"; fi; \
	if [ "$$sudo" != none ] && command -v apt-get >/dev/null 2>&1; then \
		echo "installing $(SYSTEM_PKGS) (missing:$$missing)"; \
		$$sudo apt-get update -q && \
		DEBIAN_FRONTEND=noninteractive $$sudo apt-get install -y -q --no-install-recommends \
			$(SYSTEM_PKGS) || exit 1; \
	elif [ "$(REQUIRE_SYSTEM_DEPS)" = 1 ]; then \
		echo "error: missing$$missing and cannot install $(SYSTEM_PKGS) (needs apt-get as root)" >&2; \
		exit 1; \
	else \
		echo "warning: missing$$missing; the browser/PDF report tests will be skipped" \
			"(install Debian's $(SYSTEM_PKGS))" >&2; \
	fi

test: $(PROJECT_STAMP) system-deps warm-kernels
	PYTHONPATH=$(CURDIR) $(VENV)/bin/python -m pytest -q -n $(TEST_WORKERS) --dist loadfile $(PYTEST_ARGS)

bench: $(PROJECT_STAMP)
	PYTHONPATH=$(CURDIR) $(VENV)/bin/python -m pipeline.altimeter_attitude.benchmark
	PYTHONPATH=$(CURDIR) $(VENV)/bin/python -m pipeline.bench_workflow --full-run
	PYTHONPATH=$(CURDIR) $(VENV)/bin/python -m pipeline.north_finding.benchmark

lint: $(PROJECT_STAMP)
	$(VENV)/bin/ruff check .
	$(VENV)/bin/ruff format --check .
	$(VENV)/bin/snakefmt --check Snakefile pipeline/rules/
	PYTHONPATH=$(CURDIR) $(VENV)/bin/snakemake --lint

$(UV):
	$(PYTHON) -m venv $(LOCK_TOOL_VENV)
	$(LOCK_TOOL_VENV)/bin/pip install --no-input uv==$(UV_VERSION)

# An unchanged lock keeps its old mtime, so `make lock` alone does not force a venv rebuild.
# uv keeps the existing pins where it can; to move to newer releases delete environment.lock
# first (or add --upgrade).
lock: $(UV)
	@cp -p environment.lock $(LOCK_TOOL_VENV)/environment.lock.prev 2>/dev/null || true
	$(UV) $(LOCK_ARGS)
	@if cmp -s environment.lock $(LOCK_TOOL_VENV)/environment.lock.prev; then \
		touch -r $(LOCK_TOOL_VENV)/environment.lock.prev environment.lock; \
		echo "environment.lock unchanged"; \
	fi

clean:
	rm -rf results/ .snakemake/
