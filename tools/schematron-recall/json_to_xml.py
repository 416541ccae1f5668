"""Write each X3D JSON scene under a folder as X3D XML, so that the Schematron can read it.

Usage: json_to_xml.py JSON_CORPUS OUT_FOLDER

The JSON encoding (19776-5) maps back to XML one to one: `@name` members are attributes
(arrays written as XML list values, strings of an array each in double quotes), `-name`
members hold the nodes of a node field (a containerField attribute is written only where
it differs from the node type's default in X3DUOM, as an author would write it),
`#comment` becomes a comment, `#sourceCode` the element's text, every other member an
element. One element per line, so that line numbers tell nodes apart. Files that do not
parse as JSON are skipped and counted.
"""

import json
import sys
from pathlib import Path

from lxml import etree

ORACLE = Path(__file__).resolve().parents[3] / "shared" / "oracle"


def default_container_fields():
    defaults = {}
    for version in ["3.0", "3.1", "3.2", "3.3", "4.0", "4.1"]:
        tree = etree.parse(str(ORACLE / f"X3dUnifiedObjectModel-{version}.xml"))
        for node in tree.iter("ConcreteNode", "Statement"):
            field = node.find("InterfaceDefinition/containerField")
            if field is not None:
                defaults[node.get("name")] = field.get("default")
    return defaults


DEFAULTS = default_container_fields()


def quoted(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def attribute_text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, list):
        if value and all(isinstance(v, str) for v in value):
            return " ".join(quoted(v) for v in value)
        return " ".join(attribute_text(v) for v in value)
    return str(value)


def comment(text):
    return etree.Comment(" " + str(text).replace("--", "- -").rstrip("-") + " ")


def fill(element, members):
    for key, value in members.items():
        if key.startswith("@"):
            if ":" not in key:  # xsd:noNamespaceSchemaLocation and the like
                element.set(key[1:], attribute_text(value))
        elif key == "#comment":
            for text in value if isinstance(value, list) else [value]:
                element.append(comment(text))
        elif key == "#sourceCode":
            element.text = etree.CDATA("\n".join(value) if isinstance(value, list) else str(value))
        elif key.startswith("-"):
            field = key[1:]
            for item in value if isinstance(value, list) else [value]:
                for type_name, body in item.items():
                    if type_name == "#comment":
                        element.append(comment(body))
                        continue
                    child = etree.SubElement(element, type_name)
                    if DEFAULTS.get(type_name, "children") != field:
                        child.set("containerField", field)
                    fill(child, body)
        elif isinstance(value, dict):
            fill(etree.SubElement(element, key), value)
        elif isinstance(value, list):
            for item in value:
                if isinstance(item, dict):
                    fill(etree.SubElement(element, key), item)


def convert(source):
    document = json.loads(source.read_text(encoding="utf-8"))
    root = etree.Element("X3D")
    fill(root, {k: v for k, v in document["X3D"].items() if k not in ("encoding", "JSON schema")})
    return etree.ElementTree(root)


def main():
    corpus, out = Path(sys.argv[1]), Path(sys.argv[2])
    written = skipped = 0
    for source in sorted(p for p in corpus.rglob("*") if p.suffix in (".json", ".x3dj") and p.is_file()):
        try:
            tree = convert(source)
        except (ValueError, KeyError, AttributeError, TypeError) as error:
            print(f"skipped {source}: {error}", file=sys.stderr)
            skipped += 1
            continue
        target = out / source.relative_to(corpus).with_suffix(".x3d")
        target.parent.mkdir(parents=True, exist_ok=True)
        tree.write(str(target), xml_declaration=True, encoding="UTF-8", pretty_print=True)
        written += 1
    print(f"{written} written, {skipped} skipped", file=sys.stderr)


if __name__ == "__main__":
    main()
