"""The official ASAM XSD of each OpenSCENARIO version (shipped in asam-qc-openscenarioxml), read two ways: as a validator, and as a table of each
attribute's declared type (Double, Int, String, ...), which the parameter resolver needs to know how a value
must be written and the structural check needs to know which attributes are numbers."""

from __future__ import annotations

import functools
import importlib.util
from pathlib import Path

from lxml import etree

from ttsgc.errors import ExitCode, TtsgcError

XSD = "{http://www.w3.org/2001/XMLSchema}"
VERSIONS = {"0": "1.0.0", "1": "1.1.0", "2": "1.2.0", "3": "1.3.0"}
NUMERIC_TYPES = {"Double", "Int", "UnsignedInt", "UnsignedShort"}
INTEGER_TYPES = {"Int", "UnsignedInt", "UnsignedShort"}


class XoscFileError(TtsgcError):
    """An OpenSCENARIO file that cannot be played as written; the message names file:line."""

    exit_code = ExitCode.INVALID_SCENARIO


def version_of(root) -> str | None:
    """'1.0' .. '1.3' from the FileHeader, or None when the file names no version ttsgc knows."""
    header = root.find("FileHeader")
    if header is None or header.get("revMajor") != "1" or header.get("revMinor") not in VERSIONS:
        return None
    return f"1.{header.get('revMinor')}"


def _xsd_path(version: str) -> Path:
    # the package's folder, found without importing it (its __init__ loads the whole checker bundle)
    package = Path(importlib.util.find_spec("qc_openscenario").submodule_search_locations[0])
    return package / "schema" / VERSIONS[version.split(".")[1]] / "OpenSCENARIO.xsd"


@functools.cache
def schema(version: str) -> etree.XMLSchema:
    return etree.XMLSchema(etree.parse(str(_xsd_path(version))))


@functools.cache
def attribute_types(version: str) -> dict[tuple[str, str], str]:
    """(element tag, attribute name) -> the attribute's XSD type name, for every element of the version."""
    root = etree.parse(str(_xsd_path(version))).getroot()
    by_type: dict[str, dict[str, str]] = {}
    for complex_type in root.iter(f"{XSD}complexType"):
        if complex_type.get("name"):
            by_type[complex_type.get("name")] = {a.get("name"): a.get("type", "String")
                                                 for a in complex_type.iter(f"{XSD}attribute") if a.get("name")}
    table: dict[tuple[str, str], str] = {}
    for element in root.iter(f"{XSD}element"):
        tag, type_name = element.get("name"), element.get("type")
        for attribute, attribute_type in by_type.get(type_name, {}).items():
            known = table.get((tag, attribute))
            if known is None or (known not in NUMERIC_TYPES and attribute_type in NUMERIC_TYPES):
                table[(tag, attribute)] = attribute_type  # the few tags of two types: the stricter reading
    return table


@functools.cache
def one_of_tags(version: str) -> frozenset[str]:
    """Tags whose content is "one of" several elements. Before 1.3 the XSD wrote some of these choices
    with optional members (an empty PrivateAction validated); the standard always meant exactly one, and
    1.3's XSD says so, so ttsgc holds every version to it."""
    root = etree.parse(str(_xsd_path(version))).getroot()
    choice_types = set()
    for complex_type in root.iter(f"{XSD}complexType"):
        content = [c for c in complex_type if c.tag != f"{XSD}annotation"]
        if complex_type.get("name") and content and content[0].tag == f"{XSD}choice" and \
                content[0].get("minOccurs") != "0":
            choice_types.add(complex_type.get("name"))
    return frozenset(e.get("name") for e in root.iter(f"{XSD}element") if e.get("type") in choice_types)


def errors(tree, version: str, limit: int = 10) -> list[tuple[int, str, str | None]]:
    """(line, message, XPath of the element) of the first `limit` XSD violations; empty when it is valid."""
    validator = schema(version)
    if validator.validate(tree):
        return []
    return [(e.line, e.message, e.path) for e in list(validator.error_log)[:limit]]
