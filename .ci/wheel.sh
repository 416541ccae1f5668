#!/usr/bin/env bash
# The Python package as a user gets it: builds the wheel once (maturin from PyPI, into the
# shared target/, so the release build of `cargo test --workspace --release` is reused as far
# as features allow), then installs it into a fresh venv whose PATH has no cargo or rustc
# and runs the Python tests, `x3dcheck --version` and a check of a corpus scene through
# the installed command. `.ci/run` calls it after the tests; it runs on its own too:
# `bash .ci/wheel.sh` (from any directory). The wheel is left in target/wheels/.
set -euo pipefail

cd "$(dirname "$0")/.."
repo="$PWD"

# The manylinux policy the wheel is checked against (maturin's auditwheel check, which
# fails rather than bundle a library). The extension needs glibc 2.35 symbols when built on
# Debian 12 (hypot, the pthread functions glibc 2.34 moved into libc) and libstdc++'s
# GLIBCXX_3.4.29 (glslang), both within manylinux_2_35. Wider wheels (manylinux2014) are
# built in the manylinux container by a release job: see README.md, "Python wheel".
compatibility="${X3DCHECK_WHEEL_COMPATIBILITY:-manylinux_2_35}"

timed() {
    local what="$1" started=$SECONDS
    shift
    printf '\n-- %s\n' "$what"
    "$@"
    printf -- '-- %s: %d s\n' "$what" $((SECONDS - started))
}

if ! python3 -c 'import ensurepip, venv' >/dev/null 2>&1 && command -v apt-get >/dev/null 2>&1; then
    apt-get install -y -q --no-install-recommends python3 python3-venv
fi

tools=target/ci/maturin-venv
wheels=target/wheels
venv=target/ci/wheel-venv

install_maturin() {
    [ -x "$tools/bin/maturin" ] || python3 -m venv "$tools"
    # The range pyproject.toml's build-system asks for.
    "$tools/bin/pip" install --quiet --disable-pip-version-check 'maturin>=1.9,<2'
    "$tools/bin/maturin" --version
}

build_wheel() {
    rm -f "$wheels"/x3dcheck-*.whl
    "$tools/bin/maturin" build --release --manifest-path bindings/python/Cargo.toml \
        --compatibility "$compatibility" --auditwheel check --out "$wheels"
    ls -l "$wheels"/x3dcheck-*.whl
}

# PATH without any directory holding cargo or rustc (rustup's ~/.cargo/bin, a system
# toolchain's /usr/bin entries would be found too: then the install is refused below).
path_without_rust() {
    local dir kept=""
    local IFS=:
    for dir in $PATH; do
        [ -n "$dir" ] || continue
        if [ -e "$dir/cargo" ] || [ -e "$dir/rustc" ]; then
            continue
        fi
        kept="${kept:+$kept:}$dir"
    done
    printf '%s' "$kept"
}

install_wheel() {
    rm -rf "$venv"
    python3 -m venv "$venv"
    # --only-binary: pip may not fall back to building anything from source.
    "$venv/bin/pip" install --quiet --disable-pip-version-check --only-binary=:all: \
        "$wheels"/x3dcheck-*.whl pytest
}

timed "maturin (PyPI)" install_maturin
timed "wheel build (maturin build --release)" build_wheel

# From here on, nothing can compile Rust: neither cargo nor rustc is on PATH, and the
# toolchain's homes are hidden from rustup's proxies.
export PATH="$repo/$venv/bin:$(path_without_rust)"
unset CARGO_HOME RUSTUP_HOME RUSTUP_TOOLCHAIN CARGO RUSTC
if command -v cargo >/dev/null 2>&1 || command -v rustc >/dev/null 2>&1; then
    echo "error: cargo or rustc is still on PATH: $(command -v cargo rustc)" >&2
    exit 1
fi
echo "no cargo or rustc on PATH: $PATH"

timed "install the wheel into a fresh venv" install_wheel
timed "Python tests (pytest)" python -m pytest -q bindings/python/tests
timed "x3dcheck --version (installed command)" x3dcheck --version

check_scene() {
    local scene="$1" installed expected
    if [ "$(command -v x3dcheck)" != "$repo/$venv/bin/x3dcheck" ]; then
        echo "error: x3dcheck on PATH is $(command -v x3dcheck), not the venv's" >&2
        exit 1
    fi
    installed="$(x3dcheck --level deep --format concise --exit-zero "$scene")"
    printf '%s\n' "$installed" | sed -n '1,5p'
    # The installed command is the real command line: the same report as the binary.
    expected="$(target/release/x3dcheck --level deep --format concise --exit-zero "$scene")"
    if [ "$installed" != "$expected" ]; then
        echo "error: the installed x3dcheck and target/release/x3dcheck report $scene differently" >&2
        diff <(printf '%s\n' "$expected") <(printf '%s\n' "$installed") >&2 || true
        exit 1
    fi
}
# A real scene written by others (../shared/corpus).
scene="${X3DCHECK_WHEEL_SCENE:-../shared/corpus/titania/miscellaneous/logo/website/welcome/welcome.x3d}"
timed "check $scene (installed command)" check_scene "$scene"
