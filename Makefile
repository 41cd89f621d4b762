# repro: regenerate "A Generalized Traction Curve for EHL Contacts" from first principles.
CARGO ?= cargo
LEVEL ?= 7

.PHONY: build test figures table4 lint clean

build:
	$(CARGO) build --release

# The test command of the README and of .ci/run.
test:
	$(CARGO) test --release --all-targets

# Regenerate the paper's artefacts (for now: Table 4, the grid-convergence study).
figures: build
	./target/release/repro table4

table4: build
	./target/release/repro table4

lint:
	$(CARGO) fmt --all -- --check
	$(CARGO) clippy --all-targets -- -D warnings

clean:
	$(CARGO) clean
