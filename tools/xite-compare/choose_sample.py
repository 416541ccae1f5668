#!/usr/bin/env python3
"""Chooses the fixed sample of real scenes (sample.txt) from ../shared/corpus.

Run once; the list it printed is committed as sample.txt, and the harness reads that
list, not this script, so the sample stays fixed while the corpus grows.

    python3 choose_sample.py ../../../shared/corpus > sample.txt

How: every scene file (any encoding, gzip or not) is searched for node names. A scene
is a candidate when it draws something (a Shape), is not deliberately broken (no
"bad", "error", "warning" or "parsetest" in its path) and looks the same at every moment:
no Script, no looping TimeSensor (x3dcheck draws the scene as written, a browser runs it),
nothing neither tool draws alike for reasons known in advance (NURBS, HAnim, shaders,
particles, geospatial). Each category below then takes its quota of candidates that
contain its nodes, spread evenly over the candidates in path order (so every source
folder is reached), skipping scenes already taken and the JSON twin of a taken XML
scene. Image-texture scenes must have an image file they name beside them in the
corpus. Environment scenes (panoramas, cube maps, EnvironmentLight) need not have a Shape. EXTRA lists the scenes taken by hand, each with its reason.
"""

import gzip
import os
import re
import sys

EXTENSIONS = (".x3d", ".x3dv", ".wrl", ".json", ".x3dj", ".gz", ".x3dvz")

ENVIRONMENT = (
    r"\b(front|back|left|right|top|bottom)Url\b|\bTextureBackground\b"
    r"|\b(Composed|Image)CubeMapTexture\b|\bEnvironmentLight\b"
)

# (category, quota, pattern that the scene must contain)
CATEGORIES = [
    ("physical material", 4, r"\bPhysicalMaterial\b"),
    ("unlit material", 2, r"\bUnlitMaterial\b"),
    ("image texture", 8, r"\bImageTexture\b"),
    ("pixel texture", 2, r"\bPixelTexture\b"),
    ("multitexture", 3, r"\bMultiTexture\b"),
    ("texture transform/coordinates", 3, r"\bTextureTransform\b|\bTextureCoordinateGenerator\b"),
    ("spot light", 3, r"\bSpotLight\b"),
    ("point light", 3, r"\bPointLight\b"),
    ("directional light", 4, r"\bDirectionalLight\b"),
    ("transparency", 6, r"transparency[\"'\s:=]+[\"\s]*0?\.[0-9]*[1-9]"),
    ("lines", 6, r"\b(IndexedLineSet|LineSet)\b"),
    ("points", 2, r"\bPointSet\b"),
    ("text", 6, r"\bText\b"),
    ("extrusion", 6, r"\bExtrusion\b"),
    ("elevation grid", 5, r"\bElevationGrid\b"),
    ("background", 6, r"\bBackground\b"),
    ("fog", 3, r"\bFog\b"),
    ("layering", 2, r"\bLayerSet\b"),
    ("inline", 3, r"\bInline\b"),
    ("colour per vertex", 3, r"\bColor(RGBA)?\b"),
    ("geometry 2D", 2, r"\b(Disk2D|Rectangle2D|Circle2D|Arc2D|TriangleSet2D)\b"),
    ("no viewpoint", 4, None),
    # Panoramas (Background urls, TextureBackground), cube map textures and EnvironmentLight,
    # all of them: scenes with no Shape count here (a panorama is drawn), and so do those
    # whose images are missing from the corpus (both tools then show what is left).
    ("environment", 40, ENVIRONMENT),
]

EXCLUDED = re.compile(
    r"\bScript\b|\bNurbs|\bHAnim|\b(ComposedShader|ShaderPart|PackagedShader)\b"
    r"|\bParticleSystem\b|\bGeo(Location|Origin|ElevationGrid|Viewpoint)\b"
    # Castle Game Engine's own nodes, which X_ITE does not know.
    r"|\b(Effect|EffectPart|ShaderTexture|GeneratedShadowMap|CommonSurfaceShader"
    r"|ProjectedTextureCoordinate|RenderedTexture|GeneratedCubeMapTexture|Skin)\b"
)
LOOPING_TIMER = re.compile(r"TimeSensor[^>}]*?\bloop[\"'\s:=]+[\"\s]*(true|TRUE)")
# Taken whatever the filters say, with the reason.
EXTRA = [
    # One of the corpus's few X3D 4 physical-material scenes; its Script only sets X_ITE's
    # browser options (Phong shading, high primitive quality), as the harness does.
    ("physical material", "create3000-media/docs/examples/Shape/Appearance/Appearance.x3d"),
]
BROKEN_PATH = re.compile(r"bad|error|warning|parsetest", re.IGNORECASE)
IMAGE_URL = re.compile(r"[\"']([^\"'\s]+\.(?:png|jpe?g|gif|hdr|dds|ktx2))[\"']", re.IGNORECASE)


def pattern_text(pattern):
    return pattern or ""


def stem_of(relative):
    """The file name without extension: XML and JSON twins (and copies of a scene in two
    source folders) share it."""
    return os.path.splitext(os.path.basename(relative))[0].lower()


def read_text(path):
    data = open(path, "rb").read()
    if data[:2] == b"\x1f\x8b":
        data = gzip.decompress(data)
    return data.decode("utf-8", "replace")


def textures_present(path, text):
    """Whether at least one image the scene names exists beside it."""
    urls = [u for u in IMAGE_URL.findall(text) if "://" not in u]
    folder = os.path.dirname(path)
    return any(os.path.isfile(os.path.normpath(os.path.join(folder, u))) for u in urls)


def main(corpus):
    candidates = []
    for folder, dirs, files in os.walk(corpus):
        dirs.sort()
        for name in sorted(files):
            if not name.endswith(EXTENSIONS):
                continue
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, corpus)
            if BROKEN_PATH.search(relative):
                continue
            try:
                text = read_text(path)
            except (OSError, EOFError):
                continue
            # VRML 1.0 is neither X3D nor VRML97: neither tool reads it.
            if EXCLUDED.search(text) or text.startswith("#VRML V1.0"):
                continue
            if not re.search(r"\bShape\b", text) and not re.search(ENVIRONMENT, text):
                continue
            if LOOPING_TIMER.search(text):
                continue
            candidates.append((relative, path, text))
    candidates.sort()

    taken = list(EXTRA)
    stems = {stem_of(relative) for _, relative in EXTRA}
    for category, quota, pattern in CATEGORIES:
        # Only the environment category takes scenes that draw no Shape.
        drawing = [
            c for c in candidates if pattern == ENVIRONMENT or re.search(r"\bShape\b", c[2])
        ]
        if pattern is None:
            matching = [
                c for c in drawing if not re.search(r"\b(Ortho)?Viewpoint\b", c[2])
            ]
        else:
            matching = [c for c in drawing if re.search(pattern, c[2])]
        if "ImageTexture" in pattern_text(pattern):
            matching = [c for c in matching if textures_present(c[1], c[2])]
        step = max(1, len(matching) // quota)
        chosen = []
        # Every step-th candidate, or the next fresh one after it.
        for start in range(0, len(matching), step):
            if len(chosen) == quota:
                break
            for relative, _, _ in matching[start : start + step]:
                stem = stem_of(relative)
                if stem not in stems:
                    stems.add(stem)
                    chosen.append(relative)
                    taken.append((category, relative))
                    break
        print(f"# {category}: {len(chosen)} of {len(matching)} candidates", file=sys.stderr)

    print("# The fixed sample of tools/xite-compare: one scene per line, relative to")
    print("# ../shared/corpus, after the category it was chosen for. Chosen by")
    print("# choose_sample.py (its docstring says how); edit by hand only with a reason.")
    for category, relative in taken:
        print(f"{relative}\t# {category}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "../../../shared/corpus")
