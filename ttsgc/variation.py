"""Standard parameter variation: N variants of one bound scene (the scene's speeds, scaled together so that
no follower outruns its leader; trigger distances; start positions along the lane, which vary the gaps), written as one scenario with ParameterDeclarations and a Deterministic
ParameterValueDistribution file beside it, plus the concrete files for players that do not read distributions.

The scenario's parameters are found, not guessed: every variant is emitted in full, and each attribute whose
value differs between the variants becomes a parameter (named by its owner and meaning: c1_speed, c1_s,
c1_trigger_distance, main_delay...). So the template with variant k's value set is, value for value, the
concrete file of variant k; the emitter's derived numbers (stage durations, the stop time) vary with it.
"""

from __future__ import annotations

import random
import re
from dataclasses import dataclass

from lxml import etree

from ttsgc.binding.place import CLEARANCE_M
from ttsgc.binding.scene import BoundScene
from ttsgc.errors import ExitCode, TtsgcError

SPEED_SPREAD = 0.15  # the scene's speeds times 1 +- this, together: agents queued in a lane keep their order
TRIGGER_SPREAD = 0.2  # each trigger distance times 1 +- this
START_SHIFT_M = 1.5  # each vehicle's start moved along its lane by up to this, where the lane has room
ROAD_END_MARGIN_M = 0.5
DISTRIBUTION_VERSIONS = ("1.1", "1.2", "1.3")  # ParameterValueDistribution is in the XSD from 1.1

MEANING = {("AbsoluteTargetSpeed", "value"): "speed", ("LanePosition", "s"): "s",
           ("RelativeDistanceCondition", "value"): "trigger_distance", ("DistanceCondition", "value"): "distance",
           ("Condition", "delay"): "delay", ("SimulationTimeCondition", "value"): "time",
           ("LaneChangeActionDynamics", "value"): "lane_change", ("RelativeLanePosition", "ds"): "ds"}


class VariationError(TtsgcError):
    """The variants cannot be written as one parameterised scenario (a fault in ttsgc)."""


class DistributionRequestError(TtsgcError):
    """--distribution asked for with options it cannot go with: a bad command line."""

    exit_code = ExitCode.INVALID_SCENARIO


def variants(scene: BoundScene, n: int, seed: int, road_lengths: dict[str, float]) -> list[BoundScene]:
    """n scenes on the scene's road: the first is the scene itself, the others drawn from a generator seeded
    with the seed and the variant's number (deterministic)."""
    scenes = [scene]
    for k in range(2, n + 1):
        rng = random.Random(f"ttsgc-variant:{seed}:{k}")
        tempo = 1 + rng.uniform(-SPEED_SPREAD, SPEED_SPREAD)
        agents = []
        for agent in scene.agents:
            update = {"speed_mps": round(agent.speed_mps * tempo, 3)}
            if agent.trigger is not None and agent.trigger.within_m is not None:
                within = round(max(1.0, agent.trigger.within_m * (1 + rng.uniform(-TRIGGER_SPREAD, TRIGGER_SPREAD))), 3)
                update["trigger"] = agent.trigger.model_copy(update={"within_m": within})
            shift = round(rng.uniform(-START_SHIFT_M, START_SHIFT_M), 2)
            if agent.start is not None and agent.cross_to is None and agent.walk_to is None:
                update["start"] = agent.start.model_copy(update={"s": round(agent.start.s + shift, 3)})
                if agent.route:  # a route through a junction begins where its driver starts
                    update["route"] = (update["start"],) + tuple(agent.route[1:])
            agents.append(agent.model_copy(update=update))
        scenes.append(scene.model_copy(update={"agents": tuple(_keep_room(scene.agents, agents, road_lengths))}))
    return scenes


def _keep_room(nominal, moved, road_lengths: dict[str, float]):
    """Undo a start shift that leaves the road piece or brings two bodies of one lane closer than placement
    allows (half lengths plus the clearance), so no variant overlaps at t = 0."""
    result = list(moved)
    for i, agent in enumerate(result):
        if agent.start is None or agent.start == nominal[i].start:
            continue
        length = road_lengths.get(agent.start.road, 0.0)
        ok = ROAD_END_MARGIN_M <= agent.start.s <= length - ROAD_END_MARGIN_M
        for j, other in enumerate(result):
            if j == i or other.start is None or (other.start.road, other.start.lane) != (agent.start.road,
                                                                                       agent.start.lane):
                continue
            room = (agent.length + other.length) / 2 + CLEARANCE_M
            if abs(agent.start.s - other.start.s) < room:
                ok = False
        if not ok:
            result[i] = agent.model_copy(update={"start": nominal[i].start, "route": nominal[i].route})
    return result


@dataclass(frozen=True)
class Parameterised:
    template: bytes  # the scenario, with $parameters and their declarations (nominal values)
    names: list[str]  # parameter names, in declaration order
    values: list[list[str]]  # per variant, one value per name


def _owner(element: etree._Element) -> str:
    """Whom a number belongs to: the entity of its Private or ManeuverGroup, else its Act, else the story."""
    for ancestor in element.iterancestors():
        if ancestor.tag == "Private":
            return ancestor.get("entityRef")
        if ancestor.tag == "ManeuverGroup":
            actor = ancestor.find("Actors/EntityRef")
            if actor is not None:
                return actor.get("entityRef")
        if ancestor.tag == "Act":
            return ancestor.get("name")
        if ancestor.tag == "StopTrigger" and ancestor.getparent().tag == "Storyboard":
            return "stop"
    return "scene"


def parameterise(files: list[bytes]) -> Parameterised:
    """One template and N value sets from N files that differ only in numbers."""
    roots = [etree.fromstring(f, etree.XMLParser(remove_blank_text=True)) for f in files]
    walks = [list(r.iter()) for r in roots]
    if len({len(w) for w in walks}) != 1:
        raise VariationError("the variants differ in structure, not only in numbers")
    slots: dict[tuple, str] = {}
    names: list[str] = []
    columns: list[list[str]] = []
    for elements in zip(*walks):
        first = elements[0]
        if not isinstance(first.tag, str):
            continue
        if any(e.tag != first.tag or set(e.attrib) != set(first.attrib) for e in elements):
            raise VariationError(f"the variants differ in structure at <{first.tag}>")
        for attribute in first.attrib:
            values = [e.get(attribute) for e in elements]
            if len(set(values)) == 1:
                continue
            try:
                [float(v) for v in values]
            except ValueError:
                raise VariationError(f"the variants differ in <{first.tag} {attribute}>, which is not a number")
            meaning = MEANING.get((first.tag, attribute), f"{first.tag}_{attribute}")
            base = re.sub(r"\W", "_", f"{_owner(first)}_{meaning}")
            key = (base, tuple(values))
            if key not in slots:
                name, k = base, 2
                while name in names:
                    name, k = f"{base}_{k}", k + 1
                slots[key] = name
                names.append(name)
                columns.append(values)
            first.set(attribute, f"${slots[key]}")
    template = roots[0]
    declarations = template.find("ParameterDeclarations")
    if declarations is None:
        declarations = etree.Element("ParameterDeclarations")
        template.insert(list(template).index(template.find("CatalogLocations")), declarations)
    for name, column in zip(names, columns):
        etree.SubElement(declarations, "ParameterDeclaration", name=name, parameterType="double", value=column[0])
    data = etree.tostring(template, xml_declaration=True, encoding="utf-8", pretty_print=True)
    return Parameterised(data, names, [[column[k] for column in columns] for k in range(len(files))])


def distribution_file(p: Parameterised, scenario_file: str, version: str, description: str,
                      date: str) -> bytes:
    """The Deterministic ParameterValueDistribution that expands the template to the variants, one value set
    per variant (in order: permutation k is variant k + 1)."""
    from xml.etree import ElementTree

    from scenariogeneration import xosc
    from scenariogeneration.xosc.enumerations import VersionBase

    if version not in DISTRIBUTION_VERSIONS:
        raise DistributionRequestError(f"a ParameterValueDistribution is OpenSCENARIO 1.1 or later; --osc-version {version} "
                         f"cannot hold one (choose one of {', '.join(DISTRIBUTION_VERSIONS)})")
    minor = int(version.split(".")[1])
    VersionBase().setVersion(1, minor)
    multi = xosc.DeterministicMultiParameterDistribution()
    for row in p.values:
        value_set = xosc.ParameterValueSet()
        for name, value in zip(p.names, row):
            value_set.add_parameter(name, value)
        multi.add_value_set(value_set)
    deterministic = xosc.Deterministic()
    deterministic.add_multi_distribution(multi)
    document = xosc.ParameterValueDistribution(description, "ttsgc", scenario_file, deterministic,
                                               osc_minor_version=minor)
    root = etree.fromstring(ElementTree.tostring(document.get_element(), encoding="utf-8"))
    root.find("FileHeader").set("date", date)  # the scenario's own date: the same input gives the same bytes
    data = etree.tostring(root, xml_declaration=True, encoding="utf-8", pretty_print=True)
    from ttsgc.emit.xosc import validate

    validate(data, version)
    return data


def expand(template: bytes, names: list[str], row: list[str]) -> bytes:
    """The template with one value set substituted: what a player reading the distribution plays."""
    root = etree.fromstring(template, etree.XMLParser(remove_blank_text=True))
    values = dict(zip(names, row))
    for element in root.iter():
        if not isinstance(element.tag, str):
            continue
        for attribute, value in element.attrib.items():
            if value.startswith("$") and value[1:] in values:
                element.set(attribute, values[value[1:]])
    declarations = root.find("ParameterDeclarations")
    for declaration in list(declarations):
        if declaration.get("name") in values:
            declarations.remove(declaration)
    if not len(declarations):
        root.remove(declarations)
    return etree.tostring(root, xml_declaration=True, encoding="utf-8", pretty_print=True)
