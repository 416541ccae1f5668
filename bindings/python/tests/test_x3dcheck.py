"""The Python package against the command line: same findings, same JSON bytes."""

import shutil
import subprocess
import threading
import time
from pathlib import Path

import pytest

import x3dcheck

REPO = Path(__file__).resolve().parents[3]
FAIL = REPO / "corpus" / "rules" / "INDEX_OUT_OF_RANGE" / "fail.x3d"
SCENE = (
    "<X3D profile='Interchange' version='4.0'><Scene><Shape>"
    "<IndexedFaceSet coordIndex='0 1 5 -1'><Coordinate point='0 0 0 1 0 0 0 1 0'/>"
    "</IndexedFaceSet></Shape></Scene></X3D>"
)


def test_a_string_is_checked_into_typed_diagnostics():
    report = x3dcheck.check(SCENE)
    [d] = report.diagnostics
    assert isinstance(d, x3dcheck.Diagnostic)
    assert (d.code, d.severity, d.line, d.column) == ("INDEX_OUT_OF_RANGE", "error", 1, 88)
    assert d.path.startswith("/X3D/Scene/Shape")
    assert d.clause and d.file == "<stdin>"
    assert report.summary["errors"] == 1


def test_bytes_and_str_give_one_report():
    assert x3dcheck.check(SCENE.encode()).to_json() == x3dcheck.check(SCENE).to_json()


def test_to_json_is_the_command_line_json():
    report = x3dcheck.check(FAIL.read_bytes(), path=str(FAIL))
    cli = subprocess.run(
        [shutil.which("x3dcheck"), str(FAIL), "--format", "json"],
        capture_output=True,
        text=True,
    )
    assert cli.returncode == 1, cli.stderr
    assert report.to_json() == cli.stdout
    assert x3dcheck.check_file(FAIL).to_json() == cli.stdout


def test_the_command_is_the_rust_command_line():
    cli = subprocess.run(
        [shutil.which("x3dcheck"), "-", "--format", "concise"],
        input=SCENE,
        capture_output=True,
        text=True,
    )
    assert cli.returncode == 1
    assert cli.stdout.startswith("<stdin>:1:88: error[INDEX_OUT_OF_RANGE]")
    version = subprocess.run([shutil.which("x3dcheck"), "--version"], capture_output=True, text=True)
    assert version.stdout.startswith("x3dcheck ")


def test_select_ignore_and_level():
    assert x3dcheck.check(SCENE, ignore="INDEX_").diagnostics == []
    assert x3dcheck.check(SCENE, select=["all"]).summary["errors"] == 1
    assert x3dcheck.check(SCENE, level="fast").diagnostics == []
    with pytest.raises(x3dcheck.CheckError, match="NO_SUCH_CODE"):
        x3dcheck.check(SCENE, select=["NO_SUCH_CODE"])
    with pytest.raises(x3dcheck.CheckError, match="unknown level"):
        x3dcheck.check(SCENE, level="thorough")


def test_a_config_file_applies(tmp_path):
    config = tmp_path / "x3dcheck.toml"
    config.write_text('ignore = ["INDEX_OUT_OF_RANGE"]\n')
    assert x3dcheck.check(SCENE, config=config).diagnostics == []
    # Found upward from `path`, as the command line finds it.
    assert x3dcheck.check(SCENE, path=tmp_path / "scene.x3d").diagnostics == []
    config.write_text("level = 3\n")
    with pytest.raises(x3dcheck.CheckError, match="x3dcheck.toml"):
        x3dcheck.check(SCENE, config=config)


def test_an_unreadable_file_is_an_error(tmp_path):
    with pytest.raises(x3dcheck.CheckError):
        x3dcheck.check_file(tmp_path / "none.x3d")


def test_rules_are_listed():
    rules = x3dcheck.rules()
    assert "INDEX_OUT_OF_RANGE" in {r.code for r in rules}
    assert all(isinstance(r, x3dcheck.Rule) and r.doc for r in rules)


def test_the_gil_is_released_while_checking():
    # A thread that held the GIL through the check would starve the loop below: it could
    # only count between checks. The scene doubles until one check lasts long enough to
    # tell, whatever the machine's speed (from about 1.5 MB of coordinates).
    count = 100_000
    while True:
        points = " ".join(f"{i} {i} {i}" for i in range(count))
        scene = SCENE.replace("0 0 0 1 0 0 0 1 0", points)
        ticks = 0
        done = threading.Event()

        def run():
            x3dcheck.check(scene, level="deep")
            done.set()

        thread = threading.Thread(target=run)
        start = time.perf_counter()
        thread.start()
        while not done.is_set():
            ticks += 1
            time.sleep(0)
        thread.join()
        elapsed = time.perf_counter() - start
        if elapsed > 0.05 or count >= 3_200_000:
            break
        count *= 2
    assert elapsed > 0.05, "the check was too quick to tell"
    assert ticks > 100


def test_the_readme_example_runs(tmp_path, monkeypatch, capsys):
    readme = (REPO / "README.md").read_text()
    libraries = readme[readme.index("## Libraries") :]
    example = libraries.split("```python\n", 1)[1].split("```", 1)[0]
    shutil.copy(FAIL, tmp_path / "scene.x3d")
    monkeypatch.chdir(tmp_path)
    exec(example, {})
    assert "scene.x3d:5:48: error[INDEX_OUT_OF_RANGE]" in capsys.readouterr().out
