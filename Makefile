# PistonSlap: `make demo` builds, packages and simulates the FMU; `make test` runs the Rust and the fmpy tests.

PYTHON ?= python3
VENV := .venv
VENV_PYTHON := $(VENV)/bin/python
VENV_STAMP := $(VENV)/.installed
FMU := target/fmu/PistonSlap.fmu

# The Python package is used from the source tree; plots render without a display.
export PYTHONPATH := $(CURDIR)/python
export MPLBACKEND := Agg

.PHONY: fmu venv demo test thesis bench soak clean

# cargo decides what to rebuild, so this always asks it.
fmu:
	cargo build --release
	cargo run --release --bin package_fmu

# Created once from PyPI; again only when python/requirements.txt changes.
$(VENV_STAMP): python/requirements.txt
	$(PYTHON) -m venv $(VENV)
	$(VENV_PYTHON) -m pip install --quiet --disable-pip-version-check -r python/requirements.txt
	touch $@

venv: $(VENV_STAMP)

demo: fmu venv
	$(VENV_PYTHON) -m pistonslap.demo --out out

# The style gate (rustfmt, clippy with warnings as errors), the Rust tests, then the fmpy tests
# against the packaged FMU; fails if any fails.
test: fmu venv
	cargo fmt --check
	cargo clippy --all-targets -- -D warnings
	cargo test --release
	$(VENV_PYTHON) -m pytest python/tests

# Farahanchi's chapter 2 figures (constraint forces, sliding regions) and chapter 4 (20 runs of 30 + 1500 crank
# cycles): summary table and figure sheets in out/thesis.
thesis: fmu venv
	$(VENV_PYTHON) -m pistonslap.analysis forces --out out/thesis
	$(VENV_PYTHON) -m pistonslap.analysis thesis --out out/thesis

bench:
	cargo bench

# Long runs in release mode, not part of `test`: 10⁴ crank-train cycles (prescribed and free crank)
# and 10⁶ roller revolutions (in a second thread), the energy balance checked every cycle and
# revolution (about 10 minutes on the 2-CPU machine, the roller being the longest).
soak:
	cargo run --release --example soak -- 10000 1000000

clean:
	cargo clean
	rm -rf out $(VENV) python/.pytest_cache
	find python -name __pycache__ -type d -prune -exec rm -rf {} +
