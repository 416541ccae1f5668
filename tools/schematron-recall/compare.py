"""Compare the Schematron's error-level findings with x3dcheck's, file by file.

Usage: compare.py FINDINGS.jsonl CORPUS [--x3dcheck PATH] [--report x3dcheck.json]
                  [-o judged.jsonl] [--groups groups.md]

FINDINGS.jsonl is what run_schematron.py wrote. x3dcheck is run (`--level deep --format
json --no-fold`) over the same files, from CORPUS, unless --report gives its output.
Only findings with role="error" whose context node belongs to one of the components of
issue 18 are compared (a `component` statement counts for the component it names).

Each such finding gets one verdict from JUDGEMENTS below, which says per assert whether
it is a true spec error (and which x3dcheck codes report it), a Schematron bug or style
heuristic, specific to the X3D version the 2015 Schematron knew, or unsettled (no
shall-statement found, none ruled out). A true error is matched when x3dcheck reports
one of those codes on the lines of the node's start tag, or where x3dcheck reports a
defect once for several nodes: a node type in COMPONENT_LEVEL_INSUFFICIENT or the
missing or unknown profile itself, the name in HANIM_NAME_DUPLICATE or
HANIM_LIST_MISMATCH, the DEF name in USE_UNDEFINED. The table goes to standard output.
"""

import argparse
import collections
import json
import re
import subprocess
import sys
from pathlib import Path

from lxml import etree

ORACLE = Path(__file__).resolve().parents[3] / "shared" / "oracle"

COMPONENTS = {
    "Interpolation": "interpolation (19)",
    "Time": "time and sensors (8, 20-22, 30)",
    "PointingDeviceSensor": "time and sensors (8, 20-22, 30)",
    "KeyDeviceSensor": "time and sensors (8, 20-22, 30)",
    "EnvironmentalSensor": "time and sensors (8, 20-22, 30)",
    "EventUtilities": "time and sensors (8, 20-22, 30)",
    "Navigation": "navigation (23)",
    "HAnim": "HAnim (26)",
    "H-Anim": "HAnim (26)",
    "Geospatial": "geospatial (25)",
    "NURBS": "NURBS (27)",
    "Sound": "sound (16)",
    "Text": "text (15)",
    "ParticleSystems": "particle systems (40)",
    "RigidBodyPhysics": "rigid-body physics (37)",
    "CADGeometry": "CAD (32)",
    "DIS": "DIS (28)",
}

# The node types of each X3D version, the component of each, and the highest level any
# node of a component needs in a version, from X3DUOM.
NODE_COMPONENT = {}
NODES_BY_VERSION = {}
COMPONENT_LEVELS = {}


def load_uom(oracle):
    for version in ["3.0", "3.1", "3.2", "3.3", "4.0", "4.1"]:
        tree = etree.parse(str(oracle / f"X3dUnifiedObjectModel-{version}.xml"))
        names = set()
        for node in tree.iter("ConcreteNode"):
            info = node.find("InterfaceDefinition/componentInfo")
            names.add(node.get("name"))
            if info is not None:
                NODE_COMPONENT[node.get("name")] = info.get("name")
                key = (version, info.get("name"))
                COMPONENT_LEVELS[key] = max(COMPONENT_LEVELS.get(key, 0), int(info.get("level")))
        NODES_BY_VERSION[version] = names


TRUE, BUG, VERSION, UNSETTLED = "true", "bug", "version", "unsettled"


def in_x3d3(element):
    return element.tag in NODES_BY_VERSION["3.3"]


def explicit_container_field(element):
    return element.get("containerField") is not None


def non_hanim_children(element):
    """The children of an HAnimJoint that its children field does not take (Metadata
    nodes, IS and prototype instances aside)."""
    allowed = ("HAnimJoint", "HAnimSegment", "HAnimSite", "HAnimDisplacer", "IS", "ProtoInstance")
    return [c for c in element if isinstance(c.tag, str) and c.tag not in allowed and not c.tag.startswith("Metadata")]


def doc_version(element):
    return element.getroottree().getroot().get("version") or ""


KNOWN_PROFILES = {"Core", "Interchange", "CADInterchange", "Interactive", "Immersive",
                  "MedicalInterchange", "MPEG4Interactive", "Full"}


def component_statement(element):
    """True when the statement names no component level of the document's version in X3DUOM
    (a level above every node's), else a version finding of the 2015 Schematron."""
    version = doc_version(element)
    try:
        level = int(element.get("level") or 0)
    except ValueError:
        return TRUE
    highest = COMPONENT_LEVELS.get((version, element.get("name")), 0)
    return VERSION if 1 <= level <= highest else TRUE


def requirement(element, test):
    """Judge a profile-and-component test by reading the document's own statements.

    The Schematron's tests for the geospatial and HAnim nodes demand profile Immersive
    *and* a component statement, and its Navigation tests leave out the CADInterchange
    profile; a component statement alone provides its component (7.2.5.4), and X3D 4
    names H-Anim HAnim. A missing or unknown profile makes every such finding true.
    """
    root = element.getroottree().getroot()
    profile = root.get("profile") or ""
    if profile not in KNOWN_PROFILES:  # missing (required by the schema) or unknown
        return TRUE, "7.2.5.3: the profile is missing (the schema requires it) or unknown"
    wanted = re.search(r"component\[@name='([^']+)'\]\s*\[number\(@level\) ge (\d)\]", test)
    if wanted:
        name, level = wanted.group(1), int(wanted.group(2))
        head = root.find("head")
        for component in head.iter("component") if head is not None else []:
            given = component.get("name")
            try:
                given_level = int(component.get("level") or 0)
            except ValueError:
                continue
            if given == name and given_level >= level:
                return BUG, "the test demands profile Immersive besides the component statement, which alone provides the component (7.2.5.4)"
            if name == "H-Anim" and given == "HAnim" and given_level >= level:
                return VERSION, "X3D 4 names the component HAnim; the 2015 Schematron looks for H-Anim"
    # Table H.2: CADInterchange provides Navigation level 2 (NavigationInfo, Viewpoint).
    if profile == "CADInterchange" and wanted and wanted.group(1) == "Navigation" and int(wanted.group(2)) <= 2:
        return BUG, "the Navigation tests leave out CADInterchange, whose Table H.2 provides Navigation level 2"
    return TRUE, "7.2.5.3/7.2.5.4: the profile and component statements do not provide the node's component level"


# (element regex, test regex, verdict, x3dcheck codes that report it, reason). A verdict
# may be a function of the node (and the test) that returns it, or it and its reason.
# The first entry whose two patterns match a finding judges it.
REQUIRES = ["COMPONENT_LEVEL_INSUFFICIENT"]
# A finding x3dcheck reports once for the document, which every profile-and-component
# finding of the Schematron follows from.
PROFILE_CODES = ("PROFILE_UNKNOWN", "PROFILE_MISSING")
JUDGEMENTS = [
    # Profile and component requirements (7.2.5.3, 7.2.5.4): true where the document's
    # profile and component statements do not provide the node's level.
    (r"Viewpoint$", r"\)\) or \(count\(preceding::\*\[local-name\(\)='OrthoViewpoint'\]\) > 0\)",
     lambda e, test: requirement(e, test) if e.tag == "OrthoViewpoint" else
     (BUG, "operator precedence: `A and not(B) or (count(preceding::OrthoViewpoint) > 0)` fires on every viewpoint after an OrthoViewpoint"),
     REQUIRES, "7.2.5.4: OrthoViewpoint needs Navigation level 3"),
    (r"HAnim", r"component\[@name='H-Anim'\]", requirement, REQUIRES,
     "7.2.5.3/7.2.5.4: the profile and component statements must provide the node's component level"),
    (r".", r"/X3D/head/component\[@name=|/X3D\[.*@profile=", requirement, REQUIRES,
     "7.2.5.3/7.2.5.4: the profile and component statements must provide the node's component level"),
    (r"component", r"@name='Core' and", component_statement, ["COMPONENT_UNKNOWN"],
     "7.2.5.4: a component statement names a component of the document's version at one of its levels; the 2015 Schematron knows neither X3D 4's names (HAnim) nor its new levels"),
    # Nodes the 2015 Schematron has no rule for: its catch-all rule and the capitalisation
    # test that fires on correctly spelt names.
    (r".", r"^true\(\)$", lambda e: BUG if in_x3d3(e) else VERSION, [],
     "catch-all 'not handled by X3D schematron rule': an X3D 3.3 node the Schematron has no rule for (bug) or an X3D 4 node (version)"),
    (r".", r"starts-with\(lower-case\(local-name\(\)\)", lambda e: BUG if in_x3d3(e) else VERSION, [],
     "capitalisation test that fires on a correctly spelt node name (Nurbs…, HAnim…, Polyline…)"),
    (r"GeoOrigin", r"@version='3\.0'\) or \(/X3D/@version='3\.1'\)", BUG, [],
     "GeoOrigin is deprecated in 3.3 and 4 but still part of the standard (25.4.6); 'cannot be included' is wrong, and a deprecation is no error"),
    (r".", r"@version='3\.[0-4]'\)|@version='3\.2'\] or", VERSION, [],
     "'requires X3D version 3.x or greater' fires on version 4.0/4.1"),
    # Field values.
    (r".", r"not\(contains\(@(type|string|family|justify),'\"'\)\)", TRUE, ["FIELD_VALUE_SYNTAX"],
     "19776-1 5.3.x (MFString in XML): each string shall be enclosed in double quotes"),
    (r"FontStyle", r"justifyIllegalValue", TRUE, ["FIELD_ENUM_INVALID", "FIELD_VALUE_SYNTAX"],
     "15.4.1 FontStyle: the justify values are BEGIN, END, FIRST and MIDDLE"),
    (r"ProximitySensor", r"contains\(\$size,'-'\)", TRUE, ["FIELD_OUT_OF_RANGE"],
     "22.4.1 ProximitySensor: size [0,∞)"),
    (r"Geo", r"\$geoSystem1='GD'\) and not", BUG, [],
     "the GD ellipsoid list does not know 25.2.3's 'longitude_first' argument"),
    (r"Geo", r"\(\$geoSystem1=''\) or \(\$geoSystem1='GD'\)", lambda e: BUG if "GDC" in (e.get("geoSystem") or "") or "GCC" in (e.get("geoSystem") or "") else TRUE, ["GEO_SYSTEM_INVALID"],
     "25.2.3: the frame is GD, UTM or GC; 'GDC' and 'GCC' are the synonyms 25.2.3 keeps for GD and GC (as x3dcheck's GEO_SYSTEM_INVALID reads it), which the test does not know"),
    # Interpolator and sequencer key arrays: the defaults (empty arrays) are legal; the
    # count tests count an empty string as one value.
    (r"Interpolator|Sequencer", r"not\(\$keyCount >= 2\)", BUG, [],
     "19.2.2 defines f(t) for n keys, n = 1 included (f(t) = v0 everywhere): no shall-statement asks for two keys"),
    (r"Interpolator|Sequencer", r"\$key|\$keyValue", BUG, [],
     "key and keyValue default to empty arrays (19.2.2, 30.2.2): an interpolator without keys is legal; the count test counts an empty key as 1"),
    # Parents and children.
    (r".", r"parent::Collision or parent::Shape or parent::ProtoBody", TRUE, ["NODE_TYPE_NOT_ALLOWED"],
     "a geometry node outside Shape.geometry is no X3DChildNode (4.4.2.2 node-typed fields)"),
    (r"FontStyle", r"not\(parent::Text\)", TRUE, ["NODE_TYPE_NOT_ALLOWED"],
     "a FontStyle outside Text.fontStyle is no X3DChildNode (4.4.2.2)"),
    (r"GeoOrigin", r"parent::Scene or parent::Anchor", TRUE, ["NODE_TYPE_NOT_ALLOWED"],
     "GeoOrigin is no X3DChildNode: it belongs in a geoOrigin field (25.4.6; 4.4.2.2)"),
    (r"AudioClip", r"not\(parent::LoadSensor\) and not\(parent::Sound\)", BUG, [],
     "AudioClip is an X3DChildNode (through X3DSoundSourceNode and X3DTimeDependentNode) in 3.x and 4, so it may stand in any children field; X3D 4 audio graphs put it under Gain"),
    (r"HAnimJoint|HAnimSegment|HAnimDisplacer", r"not\(@containerField='(children|displacers)'\)",
     lambda e: TRUE if explicit_container_field(e) else BUG, ["CONTAINER_FIELD_INVALID"],
     "containerField omitted: the test reads the attribute, not the default ('children', 'displacers') that XML gives it (19776-1 5.1.2)"),
    (r"HAnimJoint", r"\(parent::HAnimHumanoid\) and \(@USE\) and not\(@containerField='joints'\)", TRUE, ["HANIM_LIST_MISMATCH"],
     "26.3.2 HAnimHumanoid: joints lists every joint of the skeleton; a USE of a joint under the humanoid outside joints (here the root again in skeleton) leaves it out"),
    (r"HAnimJoint", r"\*\[not\(\(local-name\(\)='HAnimJoint'\)|^\$childrenNodes$",
     lambda e: TRUE if non_hanim_children(e) else (BUG, "a Metadata child (containerField='metadata') is allowed; the test forgets Metadata* nodes"),
     ["NODE_TYPE_NOT_ALLOWED"],
     "26.3.3 HAnimJoint: children takes HAnimJoint and HAnimSegment nodes (X3DUOM: HAnimJoint|HAnimSegment), not a Transform (4.4.2.2); x3dcheck reports each such child"),
    (r"OrthoViewpoint", r"not\(\*\) or \(IS and \(count\(\*\) = 1\)\)", VERSION, [],
     "'only a single Metadata* node is allowed': X3D 4 gave viewpoints the node field navigationInfo"),
    (r".", r"not\(\*\) or \(IS and \(count\(\*\) = 1\)\)", BUG, [],
     "'only a single Metadata* node is allowed' ignores the node's own node fields (CollisionSensor.collider, GeoTouchSensor.geoOrigin)"),
    (r"CollisionSensor", r"CollisionCollection\[@containerField='collider'\]", BUG, [],
     "the test reads the containerField attribute instead of the default 'collider' CollisionCollection gets"),
    (r"DISEntityTypeMapping", r"containerField='mapping'",
     lambda e: (VERSION, "X3D 4 renamed DISEntityManager.mapping to children, DISEntityTypeMapping's default containerField") if doc_version(e).startswith("4")
     else (BUG, "the test reads the containerField attribute instead of the default 'mapping'"), [], ""),
    (r"AudioClip", r"containerField='source'", lambda e: TRUE if explicit_container_field(e) else BUG, ["CONTAINER_FIELD_INVALID"],
     "AudioClip's default containerField is 'source'"),
    (r"CADFace|CADPart", r"not\(parent::CADPart\)|not\(ancestor::CADAssembly\)", UNSETTLED, [],
     "CAD (32) is judged by the helper adding its rules: a CADFace outside CADPart, a CADPart outside CADAssembly, both as X3DChildNodes at the Scene's top (NodeIndex); no shall-statement found here"),
    # HAnim naming and modelling conventions.
    (r"HAnim", r"\(\$name and string-length\(\$name\) > 0\) or @USE", UNSETTLED, [],
     "no shall-statement found: 19775-1 26.3 gives name the default \"\" and defers to 19774-1, whose text is not available here; the 'name must be defined' of the X3D tooltips is advice"),
    (r"HAnim", r"not\(@USE\) and not\(HAnimSegment\)", BUG, [],
     "style: no shall-statement of 19775-1 26 asks for a segment under every joint (a skeleton may have joints without geometry)"),
    (r"HAnim", r"contains\(@DEF,concat\('_',@name\)\)", BUG, [],
     "style: a DEF naming convention (the message cites H-Anim C.2, VRML binding); 4.4.3 asks for no convention"),
    (r"HAnim", r"@center='0 0 0'|@center and \(string-length\(@center\) > 0\) and starts-with|translation='0 0 0'\) or|starts-with\(substring-after\(@translation", BUG, [],
     "heuristic about where joints and sites usually are (on the ground, above it, center rather than translation); no shall-statement"),
    (r"HAnimSegment", r"\(Shape\) and not\(Transform/Shape\)", BUG, [],
     "style: a segment's geometry is in the joint's coordinate system; no Transform is required"),
    (r"HAnimSite", r"ends-with\(normalize-space\(@name\),'_tip'\)", BUG, [],
     "naming convention: a site's name need not repeat its segment's name"),
    (r"HAnim", r"(following|preceding)::\*\[local-name\(\) = \$nodeName\]\[@name = \$name\]", TRUE, ["HANIM_NAME_DUPLICATE"],
     "26.3.3 / 19774-1: joint and segment names are unique within a humanoid"),
    (r"HAnimHumanoid", r"not\(preceding::\*\[@name = \$nameAttribute\]\)", BUG, [],
     "compares the humanoid's name with the name attribute of every other element (joints, meta, fields) in the file, and reports an empty name as not unique"),
    (r"HAnimJoint", r"not\(ancestor::HAnimJoint\) and not\(ancestor::HAnimHumanoid\)", BUG, [],
     "an HAnimJoint is an X3DChildNode in X3D 3.3 and 4 and may stand outside a humanoid (NodeIndex lists every node, Sunrize tools draw joints)"),
    (r"HAnimSite", r"not\(ancestor::HAnimSegment\) and not\(ancestor::HAnimHumanoid\)", BUG, [],
     "an HAnimSite is an X3DChildNode and may stand outside a humanoid"),
    (r"HAnimSegment", r"not\(local-name\(\.\.\)='HAnimJoint'\) and not\(parent::HAnimHumanoid\)", BUG, [],
     "an HAnimSegment is an X3DChildNode and may stand outside a joint"),
    (r"HAnimDisplacer", r"has unexpected parent|not\(\(local-name\(\.\.\)='HAnimJoint'\) or \(local-name\(\.\.\)='HAnimSegment'\)", TRUE, ["NODE_TYPE_NOT_ALLOWED"],
     "HAnimDisplacer is no X3DChildNode (26.3.1: an X3DGeometricPropertyNode): it belongs in a displacers field (4.4.2.2)"),
    (r".", r"not\(contains\(\$(DEF|USE),' '\)\)", BUG, [],
     "DEF and USE are xs:ID and xs:IDREF in the X3D schema (and ID/IDREF in the DTD), whose whitespace is collapsed: DEF='hanim_sacrum ' is the name hanim_sacrum, and the USE='hanim_sacrum ' beside it refers to it"),
    # Geospatial.
    (r"GeoElevationGrid", r"ancestor::GeoLOD", BUG, [],
     "no shall-statement forbids a GeoElevationGrid under GeoLOD (25.4.4: rootNode and the loaded children hold X3DChildNodes, such as a Shape with a GeoElevationGrid)"),
    (r"GeoMetadata", r"starts-with\(local-name\(\.\.\),'Geo'\)", BUG, [],
     "GeoMetadata is an X3DInfoNode (X3DChildNode) and may stand anywhere"),
    (r"GeoMetadata", r"containerField='metadata'\) or \(@containerField='data'\)", BUG, [],
     "reports an empty GeoMetadata (no children at all) as holding a node with a wrong containerField"),
    # Navigation.
    (r"Viewpoint|OrthoViewpoint", r"HAnimHumanoid", BUG, [],
     "advice (centerOfRotation) with role error"),
    (r"Viewpoint", r"retainUserOffsets='true'\) and not", VERSION, [], "retainUserOffsets exists in 4.x"),
    (r"Viewpoint", r"not\(ancestor::(LOD|Switch)\)|ancestor::(LOD|Switch)", BUG, [],
     "advice: 'behavior not guaranteed' under LOD or Switch; no shall-statement (reported as error even so)"),
    (r"Text", r"contains\(\$normalizedString,'\"\"'\)", BUG, [],
     "style: an empty string in Text.string is an empty line (15.4.2)"),
    # DEF and USE (4.4.3), met on X3D 4 audio graphs and a FontStyle.
    (r".", r"count\(preceding::\*\[@USE=\$DEF\]\) = 0", TRUE, ["USE_UNDEFINED"],
     "4.4.3: a USE shall follow its DEF"),
    (r".", r"not\(\$NodeName=\$DEFNodeName\)", TRUE, ["USE_TYPE_MISMATCH", "USE_UNDEFINED"],
     "4.4.3: USE names a node of the same type"),
    (r"AudioClip", r"@USE or @url or", BUG, [], "url may be empty (the default)"),
]


def judge(finding, element):
    for element_re, test_re, verdict, codes, reason in JUDGEMENTS:
        if re.search(element_re, finding["element"] or "") and re.search(test_re, finding["test"]):
            if callable(verdict):
                takes_test = verdict.__code__.co_argcount == 2
                verdict = verdict(element, finding["test"]) if takes_test else verdict(element)
            if isinstance(verdict, tuple):
                verdict, reason = verdict
            return verdict, codes, reason
    return None, [], "not judged"


def component_of(finding):
    if finding["element"] == "component":
        name = re.search(r"name='([^']*)'", finding["message"])
        return COMPONENTS.get(name.group(1)) if name else None
    return COMPONENTS.get(NODE_COMPONENT.get(finding["element"]))


def node_span(element, lines):
    """The lines of the node's start tag: lxml gives the line where the tag ends."""
    end = element.sourceline
    start = end
    while start > 1 and f"<{element.tag}" not in lines[start - 1]:
        start -= 1
    return start, end


def matches(diagnostic, codes, element, span, test):
    """Whether an x3dcheck finding reports what the Schematron finding on `element` does."""
    code, message = diagnostic["code"], diagnostic["message"]
    quoting = re.search(r"contains\(@(\w+),'\"'\)", test)
    if code == "FIELD_VALUE_SYNTAX" and quoting and f"`{quoting.group(1)}`" not in message:
        return False
    if code == "ROOT_CONTENT_IGNORED":
        # A node outside the Scene: x3dcheck reports it ignored and checks nothing in it.
        return span[0] <= (diagnostic.get("line") or 0) <= span[1]
    if code not in codes and not (codes is REQUIRES and code in PROFILE_CODES):
        return False
    if codes is REQUIRES:
        # Reported once per node type (with a count), or as the missing or unknown profile.
        return code in PROFILE_CODES or message.startswith(f"{element.tag} needs")
    if code == "NODE_TYPE_NOT_ALLOWED" and message.startswith(f"{element.tag}."):
        # x3dcheck reports the child a field does not take, the Schematron its parent.
        return any(span[0] <= (diagnostic.get("line") or 0) <= child.sourceline for child in element
                   if isinstance(child.tag, str))
    if code == "HANIM_NAME_DUPLICATE":
        # x3dcheck reports the second of two nodes with one name, the Schematron both.
        return f"`{element.get('name')}`" in message
    if code == "HANIM_LIST_MISMATCH":
        # Reported once per humanoid and list, naming the joints left out.
        definition = element.getroottree().xpath("//*[@DEF=$name]", name=element.get("USE") or "")
        name = definition[0].get("name") if definition else element.get("name")
        return f"`{name}`" in message
    if code == "USE_UNDEFINED":
        # x3dcheck reports the USE before its DEF, the Schematron the DEF after it.
        return f"`{element.get('DEF') or element.get('USE')}`" in message
    return span[0] <= (diagnostic.get("line") or 0) <= span[1]


def run_x3dcheck(x3dcheck, corpus, files):
    command = [x3dcheck, "--level", "deep", "--format", "json", "--no-fold", "--exit-zero"] + files
    result = subprocess.run(command, cwd=corpus, capture_output=True, text=True, check=True)
    return json.loads(result.stdout)


def write_groups(rows, path):
    """Each verdict and reason with its count, files, components and up to three asserts."""
    groups = collections.defaultdict(list)
    for row in rows:
        groups[(row["outcome"], row["reason"])].append(row)
    with open(path, "w", encoding="utf-8") as out:
        for (outcome, reason), members in sorted(groups.items(), key=lambda kv: (kv[0][0], -len(kv[1]))):
            files = len({m["file"] for m in members})
            components = collections.Counter(m["component"] for m in members)
            out.write(f"### {outcome}: {reason}\n\n{len(members)} findings in {files} files ("
                      + ", ".join(f"{c} {n}" for c, n in components.most_common()) + ")\n\n")
            for test, count in collections.Counter(m["test"] for m in members).most_common(3):
                example = next(m for m in members if m["test"] == test)
                out.write(f"- {count}× `{test[:300]}`; e.g. {example['file']}:{example['line']}: "
                          f"{example['message'][:200]}" + (f" (x3dcheck: {example['x3dcheck']})" if example["x3dcheck"] else "") + "\n")
            out.write("\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("findings", type=Path)
    parser.add_argument("corpus", type=Path)
    parser.add_argument("--x3dcheck", default=str(Path(__file__).resolve().parents[2] / "target/release/x3dcheck"))
    parser.add_argument("--report", type=Path, help="x3dcheck's JSON report instead of running it")
    parser.add_argument("--oracle", type=Path, default=ORACLE)
    parser.add_argument("-o", "--output", type=Path, help="write each judged finding here as JSON lines")
    parser.add_argument("--groups", type=Path, help="write the findings grouped by verdict and reason here (Markdown)")
    args = parser.parse_args()
    load_uom(args.oracle)

    findings = [json.loads(line) for line in open(args.findings, encoding="utf-8")]
    errors = [f for f in findings if f["role"] == "error" and component_of(f)]
    files = sorted({f["file"] for f in findings})
    report = json.load(open(args.report)) if args.report else run_x3dcheck(args.x3dcheck, args.corpus, files)
    diagnostics = {f["path"]: f["diagnostics"] for f in report["files"]}

    parser_options = etree.XMLParser(huge_tree=True, load_dtd=False, no_network=True, resolve_entities=False)
    trees = {}
    sources = {}
    rows = []
    for finding in errors:
        path = finding["file"]
        if path not in trees:
            trees[path] = etree.parse(str(args.corpus / path), parser_options)
            sources[path] = (args.corpus / path).read_text(encoding="utf-8", errors="replace").split("\n")
        element = trees[path].xpath(finding["location"])[0]
        verdict, codes, reason = judge(finding, element)
        matched = None
        if verdict == TRUE:
            span = node_span(element, sources[path])
            matched = next((d for d in diagnostics.get(path, []) if matches(d, codes, element, span, finding["test"])), None)
        outcome = "matched" if matched else {TRUE: "missed", BUG: "bug", VERSION: "version", UNSETTLED: "unsettled"}.get(verdict, "unjudged")
        rows.append({**finding, "component": component_of(finding), "outcome": outcome, "reason": reason,
                     "x3dcheck": f"{matched['code']} line {matched.get('line')}" if matched else None})

    if args.output:
        with open(args.output, "w", encoding="utf-8") as out:
            for row in rows:
                out.write(json.dumps(row) + "\n")

    if args.groups:
        write_groups(rows, args.groups)

    table = collections.defaultdict(collections.Counter)
    for row in rows:
        table[row["component"]][row["outcome"]] += 1
        table["all"][row["outcome"]] += 1
    columns = ["matched", "missed", "bug", "version", "unsettled"]
    print("| component | Schematron errors | matched by x3dcheck | missed: true | missed: Schematron bug or style"
          " | missed: version | missed: unsettled |")
    print("|---|--:|--:|--:|--:|--:|--:|")
    for component in sorted(table, key=lambda c: (c == "all", c)):
        counts = table[component]
        print(f"| {component} | {sum(counts.values())} | " + " | ".join(str(counts[k]) for k in columns) + " |"
              + (f" unjudged {counts['unjudged']}" if counts["unjudged"] else ""))

if __name__ == "__main__":
    sys.exit(main())
