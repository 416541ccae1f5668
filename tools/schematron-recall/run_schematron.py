"""Run a Web3D X3D Schematron (.sch) over every *.x3d file under a corpus folder.

Usage: run_schematron.py SCH CORPUS [-o findings.jsonl] [--only SUBSTRING]
                         [--container-field-defaults] [--oracle FOLDER]

The .sch declares no queryBinding (so XSLT 1.0) but its tests use XPath 2.0 syntax
(value comparisons such as `number(@level) ge 2`, lower-case(), ends-with()), which an
XSLT 1.0 processor rejects: libxslt (lxml) refuses the whole validator stylesheet. An
XSLT 2.0 processor runs an XSLT 1.0 stylesheet in backwards-compatible mode, where XPath
2.0 is accepted, so this runner turns the .sch into a validator stylesheet with the ISO
Schematron XSLT 1.0 skeleton that lxml ships and compiles and runs it with SaxonC-HE
(saxonche). Each scene is read by lxml without its DTD and without the network (Saxon
would fetch the DOCTYPE's DTD) and handed to Saxon as a tree.

The Schematron's containerField tests read the attribute (`not(@containerField='children')`),
which a parser that reads the X3D DTD fills in with the DTD's default. Without the DTD
(it cannot be fetched here) they fire on every node that leaves containerField to its
default. --container-field-defaults gives each element without a containerField the
default of its node type in the X3DUOM of the document's X3D version (the value that
version's DTD and schema declare), as the DTD would; the DTD's other attribute defaults
are not applied.

Writes one JSON object per finding (a failed assert or a successful report, as SVRL
gives it): file (relative to CORPUS), role, element (the context node's name), line (the
line where the context node's start tag ends, found by evaluating SVRL's location path
with lxml), location, test and message. A file the stylesheet cannot run on gets one object with role "runner-error".
"""

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path

import lxml.isoschematron
from lxml import etree
from saxonche import PySaxonProcessor

SVRL = "http://purl.oclc.org/dsdl/svrl"
ORACLE = Path(__file__).resolve().parents[3] / "shared" / "oracle"
SKELETON = Path(lxml.isoschematron.__file__).parent / "resources/xsl/iso-schematron-xslt1"


def compile_validator(xslt, sch, work):
    """The validator stylesheet: the .sch through include, abstract expansion and the SVRL skeleton."""
    current = str(sch)
    for step in ("iso_dsdl_include.xsl", "iso_abstract_expand.xsl", "iso_svrl_for_xslt1.xsl"):
        out = os.path.join(work, step.replace(".xsl", ".out.xsl"))
        executable = xslt.compile_stylesheet(stylesheet_file=str(SKELETON / step))
        executable.transform_to_file(source_file=current, output_file=out)
        current = out
    return xslt.compile_stylesheet(stylesheet_file=current)


VERSIONS = ["3.0", "3.1", "3.2", "3.3", "4.0", "4.1"]


def container_field_defaults(oracle):
    """Per X3D version, the default containerField of every node type."""
    defaults = {}
    for version in VERSIONS:
        tree = etree.parse(str(oracle / f"X3dUnifiedObjectModel-{version}.xml"))
        defaults[version] = {}
        for node in tree.iter("ConcreteNode"):
            field = node.find("InterfaceDefinition/containerField")
            if field is not None:
                defaults[version][node.get("name")] = field.get("default")
    return defaults


def read_scene(path, defaults):
    """The scene as lxml reads it with no DTD and no network, with the containerField
    defaults of its version (none when `defaults` is empty)."""
    parser = etree.XMLParser(huge_tree=True, load_dtd=False, no_network=True, resolve_entities=False)
    tree = etree.parse(str(path), parser)
    if not defaults:
        return tree
    version = tree.getroot().get("version") or ""
    if version not in defaults:  # missing or unknown: the newest of its major version
        version = "4.1" if version.startswith("4") else "3.3"
    defaults = defaults[version]
    for element in tree.iter():
        if isinstance(element.tag, str) and element.tag in defaults and "containerField" not in element.attrib:
            element.set("containerField", defaults[element.tag])
    return tree


def findings(svrl_text, scene):
    svrl = etree.fromstring(svrl_text.encode("utf-8"))
    for item in svrl.iter(f"{{{SVRL}}}failed-assert", f"{{{SVRL}}}successful-report"):
        location = item.get("location", "")
        line = None
        element = None
        if location:
            try:
                nodes = scene.xpath(location)
            except etree.XPathError:
                nodes = []
            if nodes and isinstance(nodes[0], etree._Element):
                line = nodes[0].sourceline
                element = etree.QName(nodes[0]).localname
        text = item.find(f"{{{SVRL}}}text")
        message = " ".join("".join(text.itertext()).split()) if text is not None else ""
        yield {
            "role": item.get("role") or "",
            "element": element,
            "line": line,
            "location": location,
            "test": " ".join((item.get("test") or "").split()),
            "message": message,
        }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sch", type=Path)
    parser.add_argument("corpus", type=Path)
    parser.add_argument("-o", "--output", type=Path, default=Path("schematron-findings.jsonl"))
    parser.add_argument("--only", help="check only the files whose path contains this")
    parser.add_argument("--container-field-defaults", action="store_true",
                        help="give elements the containerField default the X3D DTD declares")
    parser.add_argument("--oracle", type=Path, default=ORACLE, help="the folder of X3dUnifiedObjectModel-*.xml")
    args = parser.parse_args()
    defaults = container_field_defaults(args.oracle) if args.container_field_defaults else {}

    with PySaxonProcessor(license=False) as proc, tempfile.TemporaryDirectory() as work:
        xslt = proc.new_xslt30_processor()
        validator = compile_validator(xslt, args.sch.resolve(), work)
        scenes = sorted(p for p in args.corpus.rglob("*.x3d") if p.is_file())
        if args.only:
            scenes = [p for p in scenes if args.only in str(p)]
        with open(args.output, "w", encoding="utf-8") as out:
            for number, scene in enumerate(scenes, 1):
                relative = str(scene.relative_to(args.corpus))
                print(f"[{number}/{len(scenes)}] {relative}", file=sys.stderr)
                try:
                    tree = read_scene(scene, defaults)
                    node = proc.parse_xml(xml_text=etree.tostring(tree.getroot(), encoding="unicode"))
                    svrl_text = validator.transform_to_string(xdm_node=node)
                    if svrl_text is None:
                        raise RuntimeError(validator.error_message or "no output")
                    rows = list(findings(svrl_text, tree))
                except Exception as error:  # a broken scene (gzip, VRML text) must not stop the run
                    rows = [{"role": "runner-error", "message": str(error)}]
                for row in rows:
                    out.write(json.dumps({"file": relative, **row}) + "\n")


if __name__ == "__main__":
    main()
