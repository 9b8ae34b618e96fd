#!/usr/bin/env bash
# The cross toolchain of `make fmu`, installed pinned and cached: `build/toolchain.sh CACHE_DIR`.
#
# - win64: Debian's own Rust compiler (rustc-web, with the standard library's sources it was released with),
#   unpacked privately into CACHE_DIR so that it shadows nothing (rustup cannot fetch another target's std
#   here, and std's sources build only with their own compiler), linked by MinGW-w64's gcc; Wine runs the
#   DLL in the tests.
# - linux64 against glibc 2.28 (RHEL/Rocky 8, Ubuntu 20.04, SLES 15): cargo-zigbuild with zig's glibc stubs,
#   from PyPI into a virtual environment in CACHE_DIR.
# - The FMU Compliance Checker (modelica-tools/FMUComplianceChecker with FMI Library 2.0.3), built from the pinned
#   source archives in build/vendor/ (no package registry carries them) with Debian's cmake, natively for linux64
#   and with MinGW-w64 for win64 (run under Wine), into CACHE_DIR.
# Run again, it only checks: everything is keyed by its pinned version.
set -euo pipefail

cache=${1:?usage: build/toolchain.sh CACHE_DIR}

# Debian 12 (bookworm) packages. rustc-web comes from bookworm-security, which replaces a version when it
# publishes the next: then this fails with the versions offered, and the pins below move together.
RUST_WEB=1.96.0+dfsg1-1~deb12u2
LLVM=1:22.1.8-1~deb12u1
APT_PACKAGES=(gcc-mingw-w64-x86-64=12.2.0-14+25.2 wine=8.0~repack-4 wine64=8.0~repack-4 cmake=3.25.1-1)
RUSTC_PACKAGES=(rustc-web=$RUST_WEB libstd-rust-web-dev=$RUST_WEB libstd-rust-web-1.96=$RUST_WEB
                rust-web-src=$RUST_WEB libllvm22=$LLVM)
# PyPI
ZIG_PACKAGES=(cargo-zigbuild==0.24.1 ziglang==0.17.1)
# build/vendor/: `git archive` of FMUComplianceChecker at c704b98 (2023-10-16, its last commit) and of fmi-library
# at tag 2.0.3 (the version the checker's CMakeLists.txt clones), both BSD-3-Clause.
CHECKER=FMUComplianceChecker-c704b98 CHECKER_SHA256=e7ccc477ec02aeb459f7d8df32659e3fad5f9a88fbaf5a328783d05bf770c066
FMIL=fmi-library-2.0.3 FMIL_SHA256=ffd747e7cecec4f700c4844ae0b9f18ec27ddf44996a5c204133ddfad45d8b5b

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

# 4. The FMU Compliance Checker, fmuCheck.linux64 and fmuCheck.win64.exe.
checker_dir=$cache/$CHECKER-$FMIL
if [ ! -x "$checker_dir/fmuCheck.linux64" ] || [ ! -f "$checker_dir/fmuCheck.win64.exe" ]; then
    vendor=$(dirname "$(readlink -f "$0")")/vendor
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    for pair in "$CHECKER:$CHECKER_SHA256" "$FMIL:$FMIL_SHA256"; do
        archive=$vendor/${pair%%:*}.tar.gz
        echo "${pair#*:}  $archive" | sha256sum --check --quiet - || die "$archive is not the pinned archive"
        tar -xzf "$archive" -C "$work"
    done
    src=$work/$CHECKER
    mv "$work/$FMIL" "$src/FMIL"
    # Built offline and in C alone: FMI Library from the unpacked archive instead of a git clone, without its
    # test FMUs, the cross toolchain file handed on to FMI Library's and Expat's own configure steps, and shlwapi
    # spelt as MinGW-w64's case-sensitive file names have it.
    sed -i -e 's|^\tGIT_REPOSITORY .*|\tDOWNLOAD_COMMAND ""|' -e '/^\tGIT_TAG /d' \
        -e 's|FMILIB_BUILD_TESTS:BOOLEAN=ON|FMILIB_BUILD_TESTS:BOOLEAN=OFF|' \
        -e 's|^\t-DCMAKE_BUILD_TYPE:STRING=.*|&\n\t-DCMAKE_TOOLCHAIN_FILE:PATH=${CMAKE_TOOLCHAIN_FILE}|' \
        -e 's|^project (FMIComplianceChecker)|project (FMIComplianceChecker C)|' \
        -e 's|(${fmuCheck} Shlwapi)|(${fmuCheck} shlwapi)|' "$src/CMakeLists.txt"
    sed -i 's|^project (FMILibrary)|project (FMILibrary C)|' "$src/FMIL/CMakeLists.txt"
    sed -i 's|^project(expat)|project(expat C)|' "$src/FMIL/ThirdParty/Expat/expat-2.1.0/CMakeLists.txt"
    sed -i 's|^\(\s*\)-DCMAKE_BUILD_TYPE:STRING=.*|&\n\1-DCMAKE_TOOLCHAIN_FILE:PATH=${CMAKE_TOOLCHAIN_FILE}|' \
        "$src/FMIL/Config.cmake/fmixml.cmake"
    sed -i 's|#include <Shlwapi.h>|#include <shlwapi.h>|' "$src/src/Common/fmuChecker.c"
    grep -q 'DOWNLOAD_COMMAND ""' "$src/CMakeLists.txt" && grep -q 'CMAKE_TOOLCHAIN_FILE:PATH' "$src/CMakeLists.txt" \
        && grep -q '(${fmuCheck} shlwapi)' "$src/CMakeLists.txt" && grep -q '^project (FMILibrary C)' "$src/FMIL/CMakeLists.txt" \
        && grep -q '<shlwapi.h>' "$src/src/Common/fmuChecker.c" \
        && grep -q 'CMAKE_TOOLCHAIN_FILE:PATH' "$src/FMIL/Config.cmake/fmixml.cmake" \
        && grep -q '^project(expat C)' "$src/FMIL/ThirdParty/Expat/expat-2.1.0/CMakeLists.txt" || die "$CHECKER: the build patches did not apply"
    printf 'set(CMAKE_%s)\n' 'SYSTEM_NAME Windows' 'SYSTEM_PROCESSOR x86_64' 'C_COMPILER x86_64-w64-mingw32-gcc' \
        'RC_COMPILER x86_64-w64-mingw32-windres' 'FIND_ROOT_PATH /usr/x86_64-w64-mingw32' \
        'FIND_ROOT_PATH_MODE_PROGRAM NEVER' 'FIND_ROOT_PATH_MODE_LIBRARY ONLY' 'FIND_ROOT_PATH_MODE_INCLUDE ONLY' \
        >"$work/mingw64.cmake"
    for platform in linux64 win64; do
        say "building the FMU Compliance Checker ($CHECKER, $FMIL) for $platform"
        flags=(-DFMUCHK_FMI_PLATFORM=$platform -DFMUCHK_INSTALL_PREFIX="$work/install")
        [ $platform = linux64 ] || flags+=(-DCMAKE_TOOLCHAIN_FILE="$work/mingw64.cmake")
        mkdir "$work/$platform"
        log=$cache/$CHECKER-$platform.log
        mkdir -p "$cache"
        (cd "$work/$platform" && cmake -Wno-dev "${flags[@]}" "$src" && make -j2 && make install) >"$log" 2>&1 \
            || die "the checker's $platform build failed: $(grep -m3 -iE 'error( |:)' "$log"), the whole log in $log"
        rm "$log"
    done
    mkdir -p "$checker_dir"
    cp "$work/install/fmuCheck.linux64" "$work/install/fmuCheck.win64.exe" "$checker_dir/"
fi

# What the Makefile and the tests read: the compiler wrapper, the zigbuild venv and the checker.
ln -sfn "$rustc_dir" "$cache/rustc-win64"
ln -sfn "$zig_dir" "$cache/zigbuild"
ln -sfn "$checker_dir" "$cache/fmucheck"
say "ready: $("$rustc_dir/bin/rustc" --version), $("$zig_dir/bin/cargo-zigbuild" --version), $(x86_64-w64-mingw32-gcc --version | head -1), $(wine --version 2>/dev/null), $CHECKER with $FMIL"
