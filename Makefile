# repro: regenerate "A Generalized Traction Curve for EHL Contacts" from first principles.
CARGO ?= cargo
LEVEL ?= 7
PYTHON ?= python3
VENV ?= .venv
# Cargo's folder, shared by the Python package's build (python/ is a crate of its own, whose
# default folder would be python/target): the library and its dependencies compile once.
CARGO_TARGET_DIR ?= $(CURDIR)/target
export CARGO_TARGET_DIR

.PHONY: build test python python-test figures committed-sources table4 snapshots check lint bench clean slurm-check

build:
	$(CARGO) build --release

# The test command of the README and of .ci/run.
test:
	$(CARGO) test --release --all-targets
	$(MAKE) python-test

# The Python package (python/, `import repro`): maturin builds the abi3 wheel into the
# virtual environment $(VENV) (created with maturin, numpy, pytest, matplotlib for the
# README's example and pandas for repro.study's DataFrame, from PyPI on first use; pandas
# adds some 15 s to the 90 s of the others, measured once on this machine).
$(VENV)/bin/maturin:
	$(PYTHON) -m venv $(VENV)
	$(VENV)/bin/pip install -q --upgrade pip
	$(VENV)/bin/pip install -q "maturin>=1.5,<2" numpy pytest matplotlib pandas

python: $(VENV)/bin/maturin
	cd python && VIRTUAL_ENV=$(CURDIR)/$(VENV) $(CURDIR)/$(VENV)/bin/maturin develop --release -q

# The pytest suite compares the package with the binary (REPRO_BIN), so both are built.
python-test: build python
	REPRO_BIN=$(CARGO_TARGET_DIR)/release/repro $(VENV)/bin/python -m pytest -q python/tests

# Regenerate the paper: Tables 1-4, Figs. 1-8, the mastercurve target (beyond the paper),
# figures/summary.csv and figures/index.html
# at the working level (LEVEL, default 7). Solved cases are cached in .repro-cache/.
# The committed figures name the commit that made them, so this refuses uncommitted changes
# to what the binary is built from (the paths of SOURCES in build.rs); ALLOW_DIRTY=1 runs
# anyway, and the page then says at its top that no commit reproduces it.
figures: committed-sources build
	./target/release/repro all --level $(LEVEL)

committed-sources:
	@if [ -z "$(ALLOW_DIRTY)" ] && ! git diff --quiet HEAD -- build.rs Cargo.toml Cargo.lock src cases templates; then \
	  echo "make figures: uncommitted changes in the sources (git diff HEAD -- src cases templates ...);" \
	       "commit them first, or run ALLOW_DIRTY=1 make figures for a page marked as not reproducible" >&2; \
	  exit 1; \
	fi

# Show how the results differ from snapshots/, then make them the new baselines.
snapshots: build
	./target/release/repro check --accept

# Compare every target with snapshots/ (also part of `make test`).
check: build
	./target/release/repro check

table4: build
	./target/release/repro table4

# Criterion benchmarks (benches/solve.rs): the 5P4E hard case at level 7, the accuracy
# study's cases per level, the cost of each effect, one whole target.
bench:
	$(CARGO) bench --bench solve

# The sharded run against a real single-node Slurm (installs slurm-wlm and munge, starts and
# stops its own daemons; needs root): the array of `repro slurm fig7 --tasks 3 --level 5`,
# merged and assembled offline, byte for byte against a one-machine run. Not part of `make
# test` (too slow, too privileged); `make test` runs the same round trip as local processes.
slurm-check: build
	scripts/slurm-check.sh

lint:
	$(CARGO) fmt --all -- --check
	$(CARGO) clippy --all-targets -- -D warnings
	cd python && $(CARGO) fmt -- --check && $(CARGO) clippy --release -- -D warnings

clean:
	$(CARGO) clean
