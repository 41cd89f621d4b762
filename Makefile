# repro: regenerate "A Generalized Traction Curve for EHL Contacts" from first principles.
CARGO ?= cargo
LEVEL ?= 7

.PHONY: build test figures table4 snapshots check lint bench clean slurm-check

build:
	$(CARGO) build --release

# The test command of the README and of .ci/run.
test:
	$(CARGO) test --release --all-targets

# Regenerate the paper: Tables 1-4, Figs. 1-8, the mastercurve target (beyond the paper),
# figures/summary.csv and figures/index.html
# at the working level (LEVEL, default 7). Solved cases are cached in .repro-cache/.
figures: build
	./target/release/repro all --level $(LEVEL)

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

clean:
	$(CARGO) clean
