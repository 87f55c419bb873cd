"""Structural validation of a .xosc before anything plays it: the standard's XSD (of the file's own version)
on the file as written and again once its parameters and catalogs are resolved, then what ttsgc's reader
relies on: a road network that exists, every number finite and within bounds, lane ids that are whole
numbers, references to entities and storyboard elements that exist. Every message names file:line.

`load_scenario` is the one call a reader makes: it returns the resolved document, or raises an error with
exit code 2 (3 when the road network is missing), so nothing after it meets a value it cannot use.
"""

from __future__ import annotations

import copy
import functools
import re
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from ttsgc.errors import ExitCode
from ttsgc.files import missing_why, real_path
from ttsgc.numbers import NumberError, parse_float
from ttsgc.simulate.resolve import XML_PARSER, Resolved, resolve
from ttsgc.xsd import (NUMERIC_TYPES, XoscFileError, attribute_types, errors, one_of_tags,
                                        version_of)

MAX_FILE_BYTES = 64 * 2**20
MAX_ERRORS = 10
ANY_NUMBER = 1e9  # no quantity of a traffic scene is larger, in any unit the standard uses
BOUNDS: dict[tuple[str, str], tuple[float, float]] = {  # (tag, attribute) -> the values a scene can mean
    ("LanePosition", "s"): (0.0, 1e6),
    ("LanePosition", "offset"): (-50.0, 50.0),
    ("RelativeLanePosition", "ds"): (-1e5, 1e5),
    ("RelativeLanePosition", "dsLane"): (-1e5, 1e5),
    ("RelativeLanePosition", "offset"): (-50.0, 50.0),
    ("Dimensions", "length"): (0.0, 100.0),
    ("Dimensions", "width"): (0.0, 100.0),
    ("Dimensions", "height"): (0.0, 100.0),
    ("AbsoluteTargetSpeed", "value"): (-1000.0, 1000.0),
    ("Condition", "delay"): (0.0, 1e6),
    ("SimulationTimeCondition", "value"): (-1e6, 1e6),
    ("SpeedActionDynamics", "value"): (-1e5, 1e5),
    ("LaneChangeActionDynamics", "value"): (0.0, 1e5),
    ("RelativeDistanceCondition", "value"): (0.0, 1e6),
    ("DistanceCondition", "value"): (0.0, 1e6),
}
LANE_IDS = {("LanePosition", "laneId"): 100, ("RelativeLanePosition", "dLane"): 100,
            ("RelativeTargetLane", "value"): 100, ("AbsoluteTargetLane", "value"): 100}
STORYBOARD_ELEMENTS = ("Story", "Act", "ManeuverGroup", "Maneuver", "Event", "Action")


class MissingRoadNetwork(XoscFileError):
    exit_code = ExitCode.MAP_ERROR


@dataclass
class Scenario:
    """A scenario file that passed every check, its parameters and catalogs resolved."""

    resolved: Resolved
    xodr: Path

    @property
    def root(self):
        return self.resolved.root

    @property
    def notes(self) -> list[str]:
        return self.resolved.notes


def bounded_number(text: str, where: str, what: str, low: float = -ANY_NUMBER, high: float = ANY_NUMBER) -> float:
    """A finite number within [low, high] (the project's one number reader), or an error that names where and
    what."""
    try:
        return parse_float(text, low, high)
    except NumberError as exc:
        raise XoscFileError(f"{where}: {what} = {exc}") from None


def read_xosc(path: Path):
    """The parsed root of an .xosc file, read safely: bounded size, no entities, no DOCTYPE (validate and lint)."""
    if path.is_dir():
        raise XoscFileError(f"{path}: is a folder, not an OpenSCENARIO file")
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise XoscFileError(f"{path}: cannot read the OpenSCENARIO file: {exc.strerror}") from None
    if size > MAX_FILE_BYTES:
        raise XoscFileError(f"{path}: {size} bytes is larger than an OpenSCENARIO file ttsgc reads "
                            f"({MAX_FILE_BYTES} bytes)")
    try:
        tree = etree.parse(str(path), etree.XMLParser(**XML_PARSER))
    except OSError as exc:
        raise XoscFileError(f"{path}: cannot read the OpenSCENARIO file: {exc}") from None
    except etree.XMLSyntaxError as exc:
        raise XoscFileError(f"{path}:{exc.lineno or 0}: not well-formed XML: {exc.msg}") from None
    if tree.docinfo.doctype:
        raise XoscFileError(f"{path}: the file has a DOCTYPE, which OpenSCENARIO never needs; refused (entities "
                            f"could read other files or grow without bound)")
    return tree.getroot()


def _raise(problems: list[str]) -> None:
    if problems:
        more = "\n... and more" if len(problems) > MAX_ERRORS else ""
        raise XoscFileError("\n".join(problems[:MAX_ERRORS]) + more)


def _schema_problems(resolved: Resolved) -> list[str]:
    """XSD violations of the resolved document, each at the place it came from and with the text it had.

    A catalog entry is held to the version of its own catalog file (esmini's 1.3 catalogs serve its 1.0
    and 1.1 scenarios), so the scenario's version judges everything else and each entry is judged apart."""
    problems = _located(resolved, resolved.root.getroottree(), resolved.version, skip_entries=True)
    for entry, catalog_file in resolved.origins.items():
        if any(ancestor in resolved.origins for ancestor in entry.iterancestors()):
            continue  # a nested entry is judged with the entry that holds it
        version = _catalog_version(catalog_file)
        document = etree.Element("OpenSCENARIO")
        etree.SubElement(document, "FileHeader", revMajor="1", revMinor=version.split(".")[1],
                         date="2000-01-01T00:00:00", description="", author="")
        etree.SubElement(document, "Catalog", name="entry").append(copy.deepcopy(entry))
        problems += _located(resolved, document.getroottree(), version, origin=catalog_file)
    return problems


@functools.lru_cache(maxsize=64)
def _catalog_version(catalog_file: Path) -> str:
    return version_of(etree.parse(str(catalog_file), etree.XMLParser(**XML_PARSER)).getroot()) or "1.3"


def _located(resolved: Resolved, tree, version: str, skip_entries: bool = False, origin: Path | None = None):
    problems = []
    for line, message, xpath in errors(tree, version, MAX_ERRORS + 1):
        found = tree.xpath(xpath) if xpath else []
        element = found[0] if found and isinstance(found, list) else None
        if skip_entries and element is not None and any(e in resolved.origins for e in [element,
                                                                                      *element.iterancestors()]):
            continue
        if origin is not None:
            where = f"{origin}:{line}"
        else:
            where = resolved.where(element) if element is not None else f"{resolved.path}:{line}"
        attribute = re.search(r"attribute '(\w+)'", message)
        written = resolved.written.get((element, attribute.group(1))) if attribute and element is not None else None
        problems.append(f"{where}: {message}" + (f" (written as '{written}')" if written else ""))
    return problems


def _number_problems(resolved: Resolved) -> list[str]:
    types = attribute_types(resolved.version)
    problems = []
    for element in resolved.root.iter():
        if not isinstance(element.tag, str):
            continue
        for name, text in element.attrib.items():
            key = (element.tag, name)
            try:
                if key in LANE_IDS:
                    limit = LANE_IDS[key]
                    number = bounded_number(text, resolved.where(element), f"{element.tag} {name}", -limit, limit)
                    if not number.is_integer():
                        raise XoscFileError(f"{resolved.where(element)}: {element.tag} {name} = '{text}' is not a "
                                            f"whole number")
                elif types.get(key) in NUMERIC_TYPES:
                    bounded_number(text, resolved.where(element), f"{element.tag} {name}", *BOUNDS.get(
                        key, (-ANY_NUMBER, ANY_NUMBER)))
            except XoscFileError as exc:
                problems.append(str(exc))
    return problems


def _empty_choice_problems(resolved: Resolved) -> list[str]:
    tags = one_of_tags(resolved.version)
    return [f"{resolved.where(e)}: {e.tag} is empty; it must hold one of its kinds of element"
            for e in resolved.root.iter() if isinstance(e.tag, str) and e.tag in tags and
            not any(isinstance(child.tag, str) for child in e)]


def _intent_values() -> dict[str, frozenset[str]]:
    from ttsgc import vocabulary as words

    return {"action": frozenset(words.ACTIONS) | {""}, "movement": frozenset({"", "left", "right", "straight"}),
            "is_ego": frozenset({"true", "false"}), "behavior": frozenset(words.BEHAVIORS),
            "type": frozenset(words.AGENT_TYPES), "road_type": frozenset(words.ROAD_TYPES),
            "position": frozenset(words.POSITIONS) | {"ego"}}


def _intent_problems(resolved: Resolved) -> list[str]:
    """The ttsgc:* properties the intent checks act on must hold words the checks know."""
    allowed = _intent_values()
    problems = []
    for prop in resolved.root.iterfind("Entities/ScenarioObject/*/Properties/Property"):
        key = (prop.get("name") or "").removeprefix("ttsgc:")
        if prop.get("name", "").startswith("ttsgc:") and key in allowed and prop.get("value") not in allowed[key]:
            known = ", ".join(sorted(value or "''" for value in allowed[key]))
            problems.append(f"{resolved.where(prop)}: the intent {prop.get('name')} = '{prop.get('value')}' is not "
                            f"one ttsgc knows ({known})")
        elif key == "stage_actions" and not _stage_actions_known(prop.get("value") or ""):
            problems.append(f"{resolved.where(prop)}: the intent {prop.get('name')} = '{prop.get('value')}' is not "
                            "a list of STAGE:ACTION with actions ttsgc knows")
    return problems


def _stage_actions_known(value: str) -> bool:
    from ttsgc import intent as I
    from ttsgc import vocabulary as words

    pairs = I.parse_stage_actions(value)
    return len(pairs) == len(value.split(",")) and all(action in words.ACTIONS for _, action in pairs)


def _reference_problems(resolved: Resolved) -> list[str]:
    root = resolved.root
    entities = {o.get("name") for o in root.iterfind("Entities/ScenarioObject")} | \
        {s.get("name") for s in root.iterfind("Entities/EntitySelection")}
    elements = {e.get("name") for tag in STORYBOARD_ELEMENTS for e in root.iterfind(f"Storyboard//{tag}")}
    problems = []
    for element in root.iterfind("Storyboard//*[@entityRef]"):
        if element.get("entityRef") not in entities:
            problems.append(f"{resolved.where(element)}: {element.tag} names the entity '{element.get('entityRef')}', "
                            f"which the file does not declare (Entities: {', '.join(sorted(entities)) or 'none'})")
    for element in root.iterfind("Storyboard//StoryboardElementStateCondition"):
        if element.get("storyboardElementRef", "").split("::")[-1] not in elements:  # 1.1+: parent::child names
            problems.append(f"{resolved.where(element)}: StoryboardElementStateCondition names "
                            f"'{element.get('storyboardElementRef')}', which is no element of the storyboard")
    return problems


def road_network(resolved: Resolved) -> Path:
    logic = resolved.root.find("RoadNetwork/LogicFile")
    if logic is None or not logic.get("filepath"):
        where = resolved.where(logic if logic is not None else resolved.root)
        raise XoscFileError(f"{where}: the file names no road network (RoadNetwork/LogicFile filepath); ttsgc "
                            f"plays scenes on OpenDRIVE roads only")
    xodr = real_path(resolved.path.parent / logic.get("filepath"))
    if not xodr.is_file():
        raise MissingRoadNetwork(f"{resolved.where(logic)}: the road network '{logic.get('filepath')}' "
                                 f"{missing_why(xodr)} (looked for {xodr})")
    return xodr


def load_scenario(path: str | Path, assign: dict[str, str] | None = None) -> Scenario:
    """Read, check and resolve a scenario file; the one entry point for every reader of .xosc files.

    `assign` sets the file's own parameters (a variant of a ParameterValueDistribution)."""
    path = Path(path)
    root = read_xosc(path)
    if not isinstance(root.tag, str) or root.tag != "OpenSCENARIO":
        raise XoscFileError(f"{path}:{root.sourceline}: the root element is <{root.tag}>, not <OpenSCENARIO>")
    version = version_of(root)
    if version is None:
        raise XoscFileError(f"{path}:{root.sourceline}: no FileHeader with a known OpenSCENARIO version "
                            f"(revMajor 1, revMinor 0 to 3)")
    if root.find("Catalog") is not None:
        raise XoscFileError(f"{path}: this is a catalog, not a scenario that can be played")
    if root.find("ParameterValueDistribution") is not None:
        scenario = root.find("ParameterValueDistribution/ScenarioFile")
        named = f"; play the scenario it varies, {scenario.get('filepath')}" if scenario is not None else ""
        raise XoscFileError(f"{path}: this is a ParameterValueDistribution, not a scenario that can be played{named}")
    _raise([f"{path}:{line}: {message}" for line, message, _ in errors(root.getroottree(), version, MAX_ERRORS + 1)])
    resolved = resolve(root, path, version, assign)
    _raise(_schema_problems(resolved))
    _raise(_empty_choice_problems(resolved) + _number_problems(resolved) + _reference_problems(resolved) +
           _intent_problems(resolved))
    return Scenario(resolved, road_network(resolved))
