#!/usr/bin/env bash
# `make fmu`: builds the FMUs' binaries and packs them: `build/fmu.sh CACHE_DIR`.
# With the toolchain of build/toolchain.sh in CACHE_DIR: linux64 against glibc 2.28 and win64; without it,
# linux64 against this machine's glibc alone (it then loads only where glibc is as new as here).
set -euo pipefail
cache=${1:?usage: build/fmu.sh CACHE_DIR}
say() { printf 'make fmu: %s\n' "$*" >&2; }

zigbuild=$cache/zigbuild/bin
rustc_win64=$cache/rustc-win64/bin/rustc
args=()
win64=
if [ -x "$rustc_win64" ] && command -v x86_64-w64-mingw32-gcc >/dev/null; then
    # std built from the compiler's own sources (-Z build-std, allowed on a stable compiler by
    # RUSTC_BOOTSTRAP) in a target directory of its own: another compiler's artifacts never mix in, and
    # its build runs beside the others (the crate's codegen is one thread: a second core is idle otherwise).
    RUSTC=$rustc_win64 RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR=target/win64 \
        CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER=x86_64-w64-mingw32-gcc \
        cargo build --release --lib -Z build-std=std,panic_unwind --target x86_64-pc-windows-gnu &
    win64=$!
else
    say "no win64 binary: 'make toolchain' installs its cross compiler"
fi
if [ -x "$zigbuild/cargo-zigbuild" ]; then
    PATH=$zigbuild:$PATH cargo zigbuild --release --lib --target x86_64-unknown-linux-gnu.2.28
    args+=(--linux64 target/x86_64-unknown-linux-gnu/release/libpistonslap.so)
else
    say "linux64 built against this machine's glibc; 'make toolchain' installs the glibc 2.28 baseline and win64"
fi
cargo build --release
if [ -n "$win64" ]; then
    wait "$win64"
    args+=(--win64 target/win64/x86_64-pc-windows-gnu/release/pistonslap.dll)
fi
cargo run --release --bin package_fmu -- "${args[@]}"
