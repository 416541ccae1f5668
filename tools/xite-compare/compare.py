#!/usr/bin/env python3
"""Compares x3dcheck's --render with X_ITE over a fixed sample of corpus scenes.

    python3 compare.py [--quality balanced] [--size 400x300] [--only TEXT] [--out out]
    python3 compare.py --scenes ../../corpus/render/cube_map_cross/scene.x3d ... --out out-render

For each scene of sample.txt: X_ITE draws it in headless Chromium (render_xite.mjs),
x3dcheck draws it with `--render --camera browser` (the first Viewpoint, else the X3D
default Viewpoint, as X_ITE binds), both at the same size; SSIM (scikit-image) compares
the two images, and out/side/ gets X_ITE | x3dcheck | difference. out/summary.md lists
every scene with its SSIM, what x3dcheck reported as not drawn, X_ITE's errors and the
cause judged for the differing ones (causes.tsv), and the agreement figure.
"""

import argparse
import json
import os
import subprocess
import sys
from datetime import datetime, timezone

import numpy as np
from PIL import Image, ImageDraw
from skimage.metrics import structural_similarity

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

# Scenes at or above this SSIM agree (README, "Comparison with X_ITE", says how it was
# chosen from the pairs around it).
DEFAULT_THRESHOLD = 0.95


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--corpus", default=os.path.join(REPO, "..", "shared", "corpus"))
    p.add_argument("--sample", default=os.path.join(HERE, "sample.txt"))
    p.add_argument("--causes", default=os.path.join(HERE, "causes.tsv"))
    p.add_argument("--out", default=os.path.join(HERE, "out"))
    p.add_argument("--size", default="400x300")
    p.add_argument("--quality", default="balanced", choices=["fast", "balanced", "accurate"])
    p.add_argument("--x3dcheck", default=os.path.join(REPO, "target", "release", "x3dcheck"))
    p.add_argument("--threshold", type=float, default=DEFAULT_THRESHOLD)
    p.add_argument("--only", help="only the scenes whose path contains this text")
    p.add_argument("--scenes", nargs="+", metavar="FILE",
                   help="compare these scene files in place of the sample (e.g. the "
                   "project's corpus/render/CASE/scene.x3d): served and run from the "
                   "repository (or, outside it, their common directory), named relative "
                   "to it")
    p.add_argument("--summarize", action="store_true",
                   help="only rewrite out/summary.md from out/results.json and causes.tsv")
    p.add_argument("--reuse-xite", action="store_true",
                   help="keep X_ITE images already in --out (x3dcheck changed, X_ITE did not)")
    return p.parse_args()


def read_sample(path):
    scenes = []
    for line in open(path, encoding="utf-8"):
        line = line.split("#", 1)
        scene, category = line[0].strip(), (line[1].strip() if len(line) > 1 else "")
        if scene:
            scenes.append((scene, category))
    return scenes


def scene_files(paths):
    """(root, [(scene relative to root, "")]) for --scenes: the root is the repository
    when every file lies in it, so that causes.tsv names them as the repository does."""
    paths = [os.path.abspath(p) for p in paths]
    for path in paths:
        if not os.path.isfile(path):
            sys.exit(f"--scenes: {path} is not a file")
    root = REPO if all(p.startswith(REPO + os.sep) for p in paths) else (
        os.path.commonpath([os.path.dirname(p) for p in paths]))
    return root, [(os.path.relpath(p, root), "") for p in paths]


def read_causes(path):
    """scene → (class, explanation); class is one of CAUSE_CLASSES."""
    causes = {}
    if os.path.exists(path):
        for line in open(path, encoding="utf-8"):
            if line.strip() and not line.startswith("#"):
                scene, kind, text = line.rstrip("\n").split("\t", 2)
                if kind not in CAUSE_CLASSES:
                    sys.exit(f"{path}: unknown cause class {kind!r} for {scene}")
                causes[scene] = (kind, text)
    return causes


CAUSE_CLASSES = {
    "x3dcheck": "an x3dcheck rendering bug",
    "pending": "an x3dcheck bug whose fix is being merged (FontStyle style, UNIT statements, "
    "HAnimHumanoid children, ScreenGroup scale, Inline bounds): re-run after the merge",
    "xite": "X_ITE departs from the spec (the spec wins)",
    "reported": "what x3dcheck reports as not drawn or drawn approximately (a documented "
    "limit: FillProperties, shaders, movies, cube maps, …)",
    "extension": "nodes or field values outside the spec (a browser's own), which X_ITE "
    "draws or rejects its own way",
    "choice": "the spec leaves it to the browser (texture filtering: 18.4.9, DEFAULT "
    "filters are the browser's; the font of a family: 15.2.2.2)",
    "invalid": "the scene breaks a 'shall' (x3dcheck reports it); the tools recover "
    "differently",
    "unresolved": "looked at, cause not established yet",
}


def image_name(scene):
    return scene.replace("/", "__") + ".png"


def render_xite(args, scenes, folder):
    os.makedirs(folder, exist_ok=True)
    command = ["node", os.path.join(HERE, "render_xite.mjs"), "--corpus", args.corpus,
               "--out", folder, "--size", args.size] + scenes
    results = {}
    with subprocess.Popen(command, stdout=subprocess.PIPE, text=True) as process:
        for line in process.stdout:
            result = json.loads(line)
            results[result["scene"]] = result
            print(f"  X_ITE    {result['ms']:6d} ms  {result['scene']}"
                  + (f"  ({result['error']})" if result["error"] else ""), flush=True)
    if process.returncode:
        sys.exit(f"render_xite.mjs exited with {process.returncode}")
    return results


def render_x3dcheck(args, scene, png):
    # Run in the corpus (--scenes: their root): a file named on the command line may read
    # references from the current directory when it lies in it, as X_ITE reads them from
    # the served root (Castle's fog scenes inline ../castle/).
    command = [os.path.abspath(args.x3dcheck), scene, "--render", os.path.abspath(png),
               "--size", args.size, "--quality", args.quality, "--camera", "browser",
               "--format", "json", "--exit-zero", "-q"]
    run = subprocess.run(command, capture_output=True, text=True, timeout=600,
                         cwd=args.corpus)
    notes = []
    try:
        report = json.loads(run.stdout)
        for file in report.get("files", []):
            for d in file.get("diagnostics", []):
                if d.get("message", "").startswith("renderer:"):
                    notes.append(d["message"])
    except json.JSONDecodeError:
        pass
    error = None if run.returncode == 0 and os.path.exists(png) else (
        run.stderr.strip().splitlines() or [f"exit {run.returncode}"])[-1]
    return notes, error


def ssim(a, b):
    """SSIM of two RGB images as Wang et al. (2004) define it: Gaussian window σ = 1.5,
    population covariances, per channel, averaged."""
    return float(structural_similarity(
        a, b, channel_axis=2, data_range=255, gaussian_weights=True, sigma=1.5,
        use_sample_covariance=False))


def side_by_side(xite, ours, path, caption):
    """X_ITE | x3dcheck | |difference| × 4, with a caption line above."""
    h, w, _ = xite.shape
    diff = np.clip(np.abs(xite.astype(int) - ours.astype(int)) * 4, 0, 255).astype(np.uint8)
    canvas = Image.new("RGB", (3 * w + 8, h + 32), (255, 255, 255))
    for i, img in enumerate((xite, ours, diff)):
        canvas.paste(Image.fromarray(img), (i * (w + 4), 32))
    draw = ImageDraw.Draw(canvas)
    draw.text((4, 2), caption, fill=(90, 90, 90))
    for i, label in enumerate(("X_ITE", "x3dcheck", "|difference| x4")):
        draw.text((i * (w + 4) + 4, 17), label, fill=(0, 0, 0))
    canvas.save(path, optimize=True)


def load_rgb(path, size):
    img = Image.open(path).convert("RGB")
    if img.size != size:
        raise ValueError(f"{path}: size {img.size}, expected {size}")
    return np.asarray(img)


def versions(args):
    def run(command):
        try:
            return subprocess.run(command, capture_output=True, text=True).stdout.strip()
        except OSError:
            return "?"
    package = json.load(open(os.path.join(HERE, "node_modules", "x_ite", "package.json")))
    return {
        "x_ite": package["version"],
        "chromium": run(["chromium", "--version"]),
        "x3dcheck": run(["git", "-C", REPO, "describe", "--always", "--dirty"]),
    }


def main():
    args = parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    if args.scenes:
        args.corpus, sample = scene_files(args.scenes)
    else:
        sample = read_sample(args.sample)
    if args.only:
        sample = [s for s in sample if args.only in s[0]]
    causes = read_causes(args.causes)
    if args.summarize:
        rows = json.load(open(os.path.join(args.out, "results.json")))
        for row in rows:
            row["agrees"] = row["ssim"] is not None and row["ssim"] >= args.threshold
            row["cause"] = causes.get(row["scene"])
        summary = write_summary(args, rows, json.load(open(os.path.join(args.out, "versions.json"))))
        open(os.path.join(args.out, "summary.md"), "w").write(summary)
        print(summary.split("\n## Scenes")[0])
        return
    folders = {k: os.path.join(args.out, k) for k in ("xite", "x3dcheck", "side")}
    for folder in folders.values():
        os.makedirs(folder, exist_ok=True)

    scenes = [s for s, _ in sample]
    if args.reuse_xite:
        log = os.path.join(args.out, "xite.jsonl")
        xite = {r["scene"]: r for r in map(json.loads, open(log))} if os.path.exists(log) else {}
        missing = [s for s in scenes if s not in xite]
        if missing:
            xite.update(render_xite(args, missing, folders["xite"]))
    else:
        xite = render_xite(args, scenes, folders["xite"])
    with open(os.path.join(args.out, "xite.jsonl"), "w") as log:
        for result in xite.values():
            log.write(json.dumps(result) + "\n")

    rows = []
    for scene, category in sample:
        png = os.path.join(folders["x3dcheck"], image_name(scene))
        notes, error = render_x3dcheck(args, scene, png)
        row = {"scene": scene, "category": category, "notes": notes,
               "x3dcheck_error": error, "xite_error": xite[scene]["error"],
               "xite_console": xite[scene]["console"], "ssim": None}
        if not error and not row["xite_error"]:
            a = load_rgb(xite[scene]["png"], (width, height))
            b = load_rgb(png, (width, height))
            row["ssim"] = ssim(a, b)
            side_by_side(a, b, os.path.join(folders["side"], image_name(scene)),
                         f"SSIM {row['ssim']:.3f}  {scene}")
        row["agrees"] = row["ssim"] is not None and row["ssim"] >= args.threshold
        row["cause"] = causes.get(scene)
        rows.append(row)
        print(f"  x3dcheck SSIM {row['ssim'] if row['ssim'] is not None else float('nan'):.3f}"
              f"  {scene}" + (f"  ({error})" if error else ""), flush=True)

    json.dump(rows, open(os.path.join(args.out, "results.json"), "w"), indent=1)
    json.dump(versions(args), open(os.path.join(args.out, "versions.json"), "w"))
    summary = write_summary(args, rows, versions(args))
    open(os.path.join(args.out, "summary.md"), "w").write(summary)
    print(summary.split("\n## Scenes")[0])


def figures(rows):
    compared = [r for r in rows if r["ssim"] is not None]
    agree = [r for r in compared if r["agrees"]]
    spec_decided = [r for r in compared if not r["agrees"] and r["cause"]
                    and r["cause"][0] in ("xite", "choice")]
    return compared, agree, spec_decided


def percent(part, whole):
    return f"{len(part)} of {len(whole)} ({100 * len(part) / len(whole):.0f}%)" if whole else "—"


def write_summary(args, rows, version):
    compared, agree, spec_decided = figures(rows)
    failed = [r for r in rows if r["ssim"] is None]
    lines = [
        "# x3dcheck against X_ITE",
        "",
        f"Run {datetime.now(timezone.utc):%Y-%m-%d %H:%M} UTC: X_ITE {version['x_ite']} in "
        f"{version['chromium']} (SwiftShader WebGL), x3dcheck {version['x3dcheck']} "
        f"`--quality {args.quality} --camera browser`, {args.size}, "
        f"SSIM threshold {args.threshold}.",
        "",
        f"- scenes in the sample: {len(rows)}; compared: {len(compared)}"
        + (f"; not compared (a tool failed): {len(failed)}" if failed else ""),
        f"- agree (SSIM ≥ {args.threshold}): {percent(agree, compared)}",
        f"- counting as agreement the differences where the spec decides against X_ITE or "
        f"leaves the choice to the browser: "
        f"{percent(agree + spec_decided, compared)}",
        "",
        "Causes of the differing scenes (as judged from the side-by-side images, causes.tsv):",
        "",
    ]
    for kind, meaning in CAUSE_CLASSES.items():
        n = sum(1 for r in compared if not r["agrees"] and r["cause"] and r["cause"][0] == kind)
        lines.append(f"- {meaning}: {n}")
    unjudged = [r for r in compared if not r["agrees"] and not r["cause"]]
    lines.append(f"- not judged yet: {len(unjudged)}")
    lines += ["", "Not compared (a tool failed):", ""] if failed else []
    for r in failed:
        cause = f" — {r['cause'][0]}: {r['cause'][1]}" if r["cause"] else ""
        lines.append(f"- `{r['scene']}`: {r['x3dcheck_error'] or r['xite_error']}{cause}")
    lines += ["", "## Scenes", "",
              "| scene | chosen for | SSIM | agrees | x3dcheck notes | cause |",
              "|---|---|--:|:-:|---|---|"]
    for r in sorted(rows, key=lambda r: (r["ssim"] is not None, r["ssim"] or 0)):
        value = f"{r['ssim']:.3f}" if r["ssim"] is not None else (
            f"failed: {r['x3dcheck_error'] or r['xite_error']}")
        notes = "; ".join(sorted({n.removeprefix("renderer: ")[:60] for n in r["notes"]}))
        cause = f"{r['cause'][0]}: {r['cause'][1]}" if r["cause"] else ""
        mark = "✓" if r["agrees"] else "✗"
        lines.append(f"| `{r['scene']}` | {r['category']} | {value} | {mark} | "
                     f"{notes.replace('|', '/')} | {cause.replace('|', '/')} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
