# PistonSlap: `make demo` builds, packages and simulates the FMU; `make test` runs the Rust and the fmpy tests.

PYTHON ?= python3
VENV := .venv
VENV_PYTHON := $(VENV)/bin/python
VENV_STAMP := $(VENV)/.installed
FMU := target/fmu/PistonSlap.fmu
ENGINE_FMU := target/fmu/EngineCycle.fmu
FMU3 := target/fmu/PistonSlap3.fmu
ENGINE_FMU3 := target/fmu/EngineCycle3.fmu

PISTONSLAP := $(VENV)/bin/pistonslap
# The cross toolchain (build/toolchain.sh): pinned, unpacked once per machine.
CROSS_CACHE ?= $(or $(XDG_CACHE_HOME),$(HOME)/.cache)/pistonslap

# Plots render without a display.
export MPLBACKEND := Agg

.PHONY: designs toolchain fmu venv demo coupled test thesis bench soak film-convergence clean

# The cross compilers of win64 and of the glibc 2.28 baseline (Debian's rustc-web, MinGW-w64, Wine, cargo-zigbuild),
# pinned; installs what is missing (apt needs root), otherwise only checks.
toolchain:
	build/toolchain.sh $(CROSS_CACHE)

# cargo decides what to rebuild, so this always asks it. One binary per platform (linux64, and win64 where
# `make toolchain` ran), packed as PistonSlap.fmu and as its partner EngineCycle.fmu, and as their FMI 3.0 twins
# PistonSlap3.fmu and EngineCycle3.fmu (the same binary); the Python package carries a copy of all four.
fmu:
	build/fmu.sh $(CROSS_CACHE)
	mkdir -p python/pistonslap/fmu
	cp $(FMU) $(ENGINE_FMU) $(FMU3) $(ENGINE_FMU3) python/pistonslap/fmu/

# Created once from PyPI with the pinned versions, again only when they or the package's metadata change;
# the package is installed editable (its code and FMU copy stay in python/), with the `pistonslap` command.
$(VENV_STAMP): python/requirements.txt python/pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(VENV_PYTHON) -m pip install --quiet --disable-pip-version-check -r python/requirements.txt
	$(VENV_PYTHON) -m pip install --quiet --disable-pip-version-check --no-deps -e ./python
	touch $@

venv: $(VENV_STAMP)

demo: fmu venv
	$(PISTONSLAP) demo --out out

# PistonSlap driven by the EngineCycle FMU through the Python master (fmpy), the engine's output derivatives
# passed on as input derivatives: CSV and plots in out/coupled (EngineCycle's defaults) and out/coupled/<preset>
# for each EngineCycle preset (python/pistonslap/engine_cycle_presets.py).
coupled: fmu venv
	$(PISTONSLAP) coupled --out out/coupled
	for preset in $$($(VENV_PYTHON) -c "from pistonslap.engine_cycle_presets import PRESETS; print(*PRESETS)"); do $(PISTONSLAP) coupled --engine $$preset --out out/coupled/$$preset || exit 1; done

# The style gate (the text gate of build/text_gate.py: no history words or design/seed numbers in src/'s comments
# and the design documents; rustfmt, clippy with warnings as errors, which also compiles the tools and benches, the
# API documentation's links, ruff's formatter and linter on python/), the Rust tests of the library and of tests/,
# then the fmpy tests against the packaged FMU, its win64 binary under Wine among them, and the documentation's
# tables against what their commands print now; fails if any fails.
test: toolchain fmu venv
	$(PYTHON) build/text_gate.py
	cargo fmt --check
	cargo clippy --all-targets -- -D warnings
	RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --lib --quiet
	$(VENV)/bin/ruff format --check python
	$(VENV)/bin/ruff check python
	cargo test --release --lib --test lib
	$(VENV_PYTHON) -m pytest python/tests

# Farahanchi's chapter 2 figures (constraint forces, sliding regions) and chapter 4 (20 runs of 30 + 1500 crank
# cycles from 6 starting crank angles, the 100 from the other starts a resumable sweep on a local Dask cluster):
# summary table and figure sheets in out/thesis.
thesis: fmu venv
	cargo build --release --example roller_forces
	$(PISTONSLAP) analysis forces --forces-tool target/release/examples/roller_forces --out out/thesis
	$(PISTONSLAP) analysis thesis --out out/thesis

bench:
	cargo bench

# Long runs in release mode, not part of `test`: 10⁴ crank-train cycles (prescribed and free crank)
# and 10⁶ roller revolutions (in a second thread), the energy balance checked every cycle and
# revolution (about 10 minutes on the 2-CPU machine, the roller being the longest).
# 10⁴ random designs of the declared space (tests/common/designs.rs `declared`), then the same designs with ramping
# inputs (`declared ramped`), every output checked at every step and each run's state restored halfway: the
# failures and the count; then 10⁴ with nothing doing work on them (`declared conservative`): their worst energy
# balance without and with friction (about an hour on the 2-CPU machine). Then 10⁴ declared designs, 10⁴ ramped
# and 10⁴ roller designs through the FMU's C functions (tests/common/fmu_designs.rs): every parameter set by
# name, every output read and checked at every step, the state restored into a second instance halfway (about
# 50 minutes each for the crank train, 20 for the roller).
designs:
	cargo run --release --example random_designs -- 10000 0 declared
	cargo run --release --example random_designs -- 10000 0 "declared ramped"
	cargo run --release --example random_designs -- 10000 0 "declared conservative"
	cargo run --release --example random_designs -- 10000 0 "fmu declared"
	cargo run --release --example random_designs -- 10000 0 "fmu declared ramped"
	cargo run --release --example random_designs -- 10000 0 "fmu roller"

soak:
	cargo run --release --example soak -- 10000 1000000

# The lubricated skirt's convergence in the film relaxation τ (at the default grid) and in the film grid (at the
# default τ), the default engine at 1200 and 3000 rpm, the second cycle of each run against the first row's: the
# tables of documentation/validation/lubricated_skirt.md, which `make test` checks (seconds on the 2-CPU machine).
film-convergence:
	cargo run --release --example film_convergence -- 1200 1.25e-5:16:24 2.5e-5:16:24 5e-5:16:24 1e-4:16:24
	cargo run --release --example film_convergence -- 1200 1e-4:24:36 1e-4:16:24 1e-4:12:18 1e-4:8:12
	cargo run --release --example film_convergence -- 3000 1e-4:24:36 1e-4:16:24 1e-4:12:18 1e-4:8:12

clean:
	cargo clean
	rm -rf out $(VENV) python/.pytest_cache python/pistonslap/fmu python/build python/*.egg-info
	find python -name __pycache__ -type d -prune -exec rm -rf {} +
