"""The cost of a library call on a 1 MB scene against the command line on the same file
(README, "Libraries"). Run from the repository root, with the x3dcheck Python package
installed (pip install bindings/python), bindings/node built (npm install) and the
release binary built (cargo build --release or cargo test --release):

    python bindings/cost.py [--runs 15]

Prints the median wall and CPU time of each: the CLI as a process (`--format json` to a pipe),
the Python and Node calls in a running interpreter (the JSON report parsed into objects
included, the interpreter's start and the import not).
"""

import argparse
import json
import resource
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import x3dcheck

REPO = Path(__file__).resolve().parents[1]


def scene(shapes: int) -> str:
    """A scene of `shapes` Transforms each holding a Material and a 64-vertex IndexedFaceSet
    with one index past its coordinates (a finding per shape, so that the report has
    weight too): about 1250 bytes a shape."""
    parts = ["<X3D profile='Interchange' version='4.0'><Scene>"]
    for s in range(shapes):
        points = " ".join(f"{(i % 8) * 0.5} {(i // 8) * 0.5} {s % 7}" for i in range(64))
        faces = " ".join(f"{i} {i + 1} {i + 9} {i + 8} -1" for i in range(0, 55, 2)) + " 0 1 64 -1"
        parts.append(
            f"<Transform translation='{s} 0 0'><Shape><Appearance><Material DEF='M{s}' "
            f"diffuseColor='0.8 0.2 0.2'/></Appearance><IndexedFaceSet coordIndex='{faces}'>"
            f"<Coordinate point='{points}'/></IndexedFaceSet></Shape></Transform>\n"
        )
    parts.append("</Scene></X3D>\n")
    return "".join(parts)


def cpu_seconds() -> float:
    """CPU time (user + system) of this process and its finished children: what a call
    costs even on a loaded machine, where wall time mostly measures waiting."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def medians(run, runs: int) -> tuple:
    """Median wall and CPU seconds of `run`."""
    wall, cpu = [], []
    for _ in range(runs):
        start, start_cpu = time.perf_counter(), cpu_seconds()
        run()
        wall.append(time.perf_counter() - start)
        cpu.append(cpu_seconds() - start_cpu)
    return statistics.median(wall), statistics.median(cpu)


NODE = """
const fs = require('node:fs');
const x3dcheck = require(process.argv[1]);
const [file, runs] = [process.argv[2], Number(process.argv[3])];
const source = fs.readFileSync(file);
const median = (xs) => xs.sort((a, b) => a - b)[xs.length >> 1];
async function medians(run) {
  const wall = [];
  const cpu = [];
  for (let i = 0; i < runs; i++) {
    const [start, startCpu] = [process.hrtime.bigint(), process.cpuUsage()];
    await run();
    const used = process.cpuUsage(startCpu);
    wall.push(Number(process.hrtime.bigint() - start) / 1e9);
    cpu.push((used.user + used.system) / 1e6);
  }
  return [median(wall), median(cpu)];
}
(async () => {
  const check = await medians(() => x3dcheck.check(source, { path: file }));
  const checkAsync = await medians(() => x3dcheck.checkAsync(source, { path: file }));
  console.log(JSON.stringify({ check, checkAsync }));
})();
"""


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=15)
    runs = parser.parse_args().runs
    with tempfile.TemporaryDirectory() as tmp:
        file = Path(tmp) / "scene.x3d"
        file.write_text(scene(840))
        size = file.stat().st_size
        source = file.read_bytes()
        cli = REPO / "target" / "release" / "x3dcheck"
        report = x3dcheck.check(source, path=str(file))
        cli_json = subprocess.run([cli, file, "--format", "json"], capture_output=True, text=True).stdout
        assert report.to_json() == cli_json, "the Python report differs from the CLI's"
        results = {
            "CLI process (x3dcheck FILE --format json)": medians(
                lambda: subprocess.run([cli, file, "--format", "json"], capture_output=True), runs
            ),
            "Python x3dcheck.check(bytes)": medians(
                lambda: x3dcheck.check(source, path=str(file)), runs
            ),
            "Python x3dcheck.check_file(path)": medians(lambda: x3dcheck.check_file(file), runs),
        }
        node = subprocess.run(
            ["node", "-e", NODE, str(REPO / "bindings" / "node"), str(file), str(runs)],
            capture_output=True, text=True, check=True,
        )
        node_medians = json.loads(node.stdout)
        results["Node x3dcheck.check(buffer)"] = node_medians["check"]
        results["Node await x3dcheck.checkAsync(buffer)"] = node_medians["checkAsync"]
        print(f"{size} bytes, {len(report.diagnostics)} findings, median of {runs} runs:")
        for name, (wall, cpu) in results.items():
            print(f"  {name}: {wall * 1000:.0f} ms wall, {cpu * 1000:.0f} ms CPU")


if __name__ == "__main__":
    main()
