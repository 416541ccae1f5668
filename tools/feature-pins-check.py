#!/usr/bin/env python3
"""Checks feature-pins/: that the workspace's other builds (`cargo install --path .`,
`cargo run --example x3dcheck-bench`, maturin's and bindings/node/build.js's) enable the
same dependency features as `cargo test --workspace`, so that each reuses that build
instead of compiling x3dcheck and its dependencies again. Compares `cargo tree` feature sets per package; prints each package
whose features differ and exits 1 then. Run from anywhere: `python3 tools/feature-pins-check.py`.
"""

import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HOST = subprocess.run(
    ["rustc", "-vV"], capture_output=True, text=True, check=True
).stdout.split("host: ", 1)[1].split()[0]


def features(*selection, dev=True):
    """Package -> enabled features, as `cargo tree` resolves them for this selection."""
    edges = "normal,build,dev" if dev else "normal,build"
    out = subprocess.run(
        ["cargo", "tree", "--quiet", "--target", HOST, "-e", edges, "--prefix", "none",
         "-f", "{p}|{f}", *selection],
        capture_output=True, text=True, check=True, cwd=ROOT,
    ).stdout
    table = {}
    for line in out.splitlines():
        if "|" not in line:
            continue
        package, enabled = line.replace(" (*)", "").split("|", 1)
        table.setdefault(package, set()).update(f for f in enabled.split(",") if f)
    return table


def main():
    workspace = features("--workspace")
    builds = {
        "cargo install --path .": features("-p", "x3dcheck", dev=False),
        "cargo run --example x3dcheck-bench": features("-p", "x3dcheck"),
        "x3dcheck-node": features("-p", "x3dcheck-node", dev=False),
        # maturin enables it (bindings/python/pyproject.toml); only pyo3's own crates change.
        "x3dcheck-python": features(
            "-p", "x3dcheck-python", "--features", "x3dcheck-python/extension-module", dev=False
        ),
    }
    differ = 0
    for build, table in builds.items():
        for package in sorted(table):
            if package not in workspace or package.startswith(("pyo3", "x3dcheck-python")):
                continue
            missing = workspace[package] - table[package]
            if missing:
                differ += 1
                print(f"{build}: {package} lacks {','.join(sorted(missing))}")
    if differ:
        print(f"{differ} difference(s): add them to feature-pins/Cargo.toml "
              "(a proc macro's dependency under [build-dependencies])", file=sys.stderr)
        return 1
    print(f"{', '.join(builds)}: the dependency features of cargo test --workspace")
    return 0


if __name__ == "__main__":
    sys.exit(main())
