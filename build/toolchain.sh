#!/usr/bin/env bash
# The cross toolchain of `make fmu`, installed pinned and cached: `build/toolchain.sh CACHE_DIR`.
#
# - win64: Debian's own Rust compiler (rustc-web, with the standard library's sources it was released with),
#   unpacked privately into CACHE_DIR so that it shadows nothing (rustup cannot fetch another target's std
#   here, and std's sources build only with their own compiler), linked by MinGW-w64's gcc; Wine runs the
#   DLL in the tests.
# - linux64 against glibc 2.28 (RHEL/Rocky 8, Ubuntu 20.04, SLES 15): cargo-zigbuild with zig's glibc stubs,
#   from PyPI into a virtual environment in CACHE_DIR.
# Run again, it only checks: everything is keyed by its pinned version.
set -euo pipefail

cache=${1:?usage: build/toolchain.sh CACHE_DIR}

# Debian 12 (bookworm) packages. rustc-web comes from bookworm-security, which replaces a version when it
# publishes the next: then this fails with the versions offered, and the pins below move together.
RUST_WEB=1.96.0+dfsg1-1~deb12u2
LLVM=1:22.1.8-1~deb12u1
APT_PACKAGES=(gcc-mingw-w64-x86-64=12.2.0-14+25.2 wine=8.0~repack-4 wine64=8.0~repack-4)
RUSTC_PACKAGES=(rustc-web=$RUST_WEB libstd-rust-web-dev=$RUST_WEB libstd-rust-web-1.96=$RUST_WEB
                rust-web-src=$RUST_WEB libllvm22=$LLVM)
# PyPI
ZIG_PACKAGES=(cargo-zigbuild==0.24.1 ziglang==0.17.1)

say() { printf 'toolchain: %s\n' "$*" >&2; }
die() { say "$*"; exit 1; }

as_root() {
    if [ "$(id -u)" -eq 0 ]; then "$@"
    elif command -v sudo >/dev/null; then sudo "$@"
    else die "needs root for: $* (run it as root, or build linux64 alone with 'make fmu')"
    fi
}

# Each pinned package=version must be offered by the configured sources.
check_offered() {
    local spec name version
    for spec in "$@"; do
        name=${spec%%=*} version=${spec#*=}
        if ! apt-cache madison "$name" | awk -F'|' '{gsub(/ /, "", $2); print $2}' | grep -qxF "$version"; then
            die "$name $version is no longer offered by apt (offered: $(apt-cache madison "$name" | awk -F'|' '{gsub(/ /, "", $2); printf "%s ", $2}')); update the pins in build/toolchain.sh"
        fi
    done
}

apt_ready=
apt_update() {
    if [ -z "$apt_ready" ]; then
        command -v apt-get >/dev/null || die "apt-get not found: the cross toolchain is pinned to Debian 12 packages"
        as_root apt-get update -qq
        apt_ready=1
    fi
}

# 1. MinGW-w64 and Wine, system-wide.
missing=()
for spec in "${APT_PACKAGES[@]}"; do
    [ "$(dpkg-query -W -f '${Version}' "${spec%%=*}" 2>/dev/null || true)" = "${spec#*=}" ] || missing+=("$spec")
done
if [ ${#missing[@]} -gt 0 ]; then
    apt_update
    check_offered "${missing[@]}"
    say "installing ${missing[*]}"
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# 2. The private Rust compiler for win64.
rustc_dir=$cache/rustc-web-$RUST_WEB
if [ ! -x "$rustc_dir/bin/rustc" ]; then
    apt_update
    check_offered "${RUSTC_PACKAGES[@]}"
    say "unpacking rustc-web $RUST_WEB into $rustc_dir"
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    (cd "$work" && apt-get download -qq "${RUSTC_PACKAGES[@]}" 2>/dev/null) || die "apt-get download ${RUSTC_PACKAGES[*]} failed"
    mkdir -p "$work/root"
    for deb in "$work"/*.deb; do dpkg-deb -x "$deb" "$work/root"; done
    mkdir -p "$work/root/bin"
    # The compiler finds its sysroot (and std's sources, lib/rustlib/src/rust) from its own path; the
    # wrapper gives it its private libraries.
    cat >"$work/root/bin/rustc" <<'EOF'
#!/bin/sh
here=$(dirname "$(readlink -f "$0")")
LD_LIBRARY_PATH=$here/../usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} exec "$here/../usr/bin/rustc" "$@"
EOF
    chmod +x "$work/root/bin/rustc"
    "$work/root/bin/rustc" --version >/dev/null || die "the unpacked rustc-web does not run"
    mkdir -p "$cache"
    rm -rf "$rustc_dir"
    mv "$work/root" "$rustc_dir"
fi

# 3. cargo-zigbuild and zig for the glibc 2.28 baseline.
zig_dir=$cache/zigbuild-$(IFS=-; echo "${ZIG_PACKAGES[*]}" | tr '=' '_')
if [ ! -x "$zig_dir/bin/cargo-zigbuild" ]; then
    say "installing ${ZIG_PACKAGES[*]} into $zig_dir"
    rm -rf "$zig_dir"
    python3 -m venv "$zig_dir"
    "$zig_dir/bin/python" -m pip install --quiet --disable-pip-version-check "${ZIG_PACKAGES[@]}"
fi

# What the Makefile reads: the compiler wrapper and the zigbuild venv.
ln -sfn "$rustc_dir" "$cache/rustc-win64"
ln -sfn "$zig_dir" "$cache/zigbuild"
say "ready: $("$rustc_dir/bin/rustc" --version), $("$zig_dir/bin/cargo-zigbuild" --version), $(x86_64-w64-mingw32-gcc --version | head -1), $(wine --version 2>/dev/null)"
