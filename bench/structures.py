"""How well the lowering reads sentence structures, apart from any writer's voice: scenes generated from
templates whose reading the conventions fix, family by family (terse lists, notes one agent a line, plain
clauses joined many ways, requests, junctions, composed positions, road users' names, verbs of stopping and
going on, a vehicle named again the ways accounts do, asides that name no one in the scene, turns and lane
changes to either side), each checked agent by agent (or, where only that is fixed, type by type) against the
reading it must have.

    python bench/structures.py                 # 300 scenes a family, seed 0
    python bench/structures.py --n 1000 --seed 3 --show 5

Prints, per family, the scenes read wrong and the first few of them (text, wanted, read). A family is a kind
of sentence, not a voice: a wrong reading here is a defect of the grammar, to fix at its root with a test of
its own (tests/test_terse_lists.py holds a drawn sample of the first family).
"""

from __future__ import annotations

import argparse
import random
import sys
from collections import Counter
from pathlib import Path
from typing import Callable, Iterator

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from ttsgc.evaluate import agent_keys  # noqa: E402
from ttsgc.lowering import lower_prompt  # noqa: E402

Key = tuple[str, str, str]
Scene = tuple[str, list[Key] | Counter]  # a text and its agents: full keys, or a count by type when only that is fixed

VEHICLES = [("a truck", "truck"), ("a white van", "car"), ("an SUV", "car"), ("a motorcycle", "motorcycle"),
            ("a bus", "bus"), ("a taxi", "car"), ("a lorry", "truck"), ("a police car", "police"),
            ("an ambulance", "ambulance"), ("a sedan", "car")]


def terse_lists(draw: random.Random) -> Scene:
    egos = [("ego", "car"), ("ego car", "car"), ("Ego vehicle", "car"), ("the ego", "car"), ("ego bus", "bus"),
            ("ego truck", "truck"), ("Ego (car)", "car"), ("ego: sedan", "car"), ("the ego vehicle", "car"),
            ("my car", "car")]
    items = [("a pedestrian crossing from the right", "pedestrian"), ("cyclist on the right", "cyclist"),
             ("truck ahead braking", "truck"), ("oncoming car turning left", "car"), ("lead car braking", "car"),
             ("a bus behind", "bus"), ("motorcycle overtaking on the left", "motorcycle"),
             ("parked van on the right", "car"), ("ambulance approaching from behind", "ambulance"),
             ("child running out from the left", "pedestrian"), ("car cutting in from the left lane", "car"),
             ("SUV in front stopping", "car"), ("pedestrian waiting on the sidewalk", "pedestrian"),
             ("a police car coming the other way", "police"), ("slow tractor ahead", "truck"),
             ("bicycle on the right", "cyclist"), ("two pedestrians crossing", "pedestrian"),
             ("a van pulling out from the right", "car")]
    doings = ["", " turning left", " going straight", " turns right", " stopped at the lights",
              " changing lanes to the left"]
    (ego, ego_type), chosen = draw.choice(egos), draw.sample(items, draw.randint(1, 3))
    sep = draw.choice([", ", "; ", ". "])
    want = Counter({("ego", ego_type): 1})
    for text, kind in chosen:
        want[kind] += 2 if text.startswith("two ") else 1
    return ego + draw.choice(doings) + sep + sep.join(text for text, _ in chosen), want


def notes(draw: random.Random) -> Scene:
    egos = [("Ego", "car"), ("Ego vehicle", "car"), ("Ego (truck)", "truck"), ("EGO", "car"), ("Ego car", "car")]
    doings = [("going straight", "go_straight"), ("stopped", "stop"), ("lane change left", "change_lane_to_left")]
    agents = [("Truck", "truck"), ("Van", "car"), ("Motorbike", "motorcycle"), ("Bus", "bus"), ("SUV", "car"),
              ("Ambulance", "ambulance"), ("Police car", "police"), ("HGV", "truck")]
    acts = [("braking hard", "stop"), ("stationary", "stop"), ("going straight", "go_straight")]
    places = [("ahead", "front"), ("behind", "back"), ("left lane, ahead", "front_left"), ("in front of ego", "front"),
              ("right lane, level with ego", "right"), ("behind ego", "back"), ("rear", "back")]
    (ego, ego_type), (doing, ego_act) = draw.choice(egos), draw.choice(doings)
    chosen = draw.sample(agents, draw.randint(1, 3))
    lines, want = [], [(ego_type, ego_act, "ego")]
    for name, kind in chosen:
        (act, action), (place, position) = draw.choice(acts), draw.choice(places)
        lines.append((name, f"{place}, {act}" if draw.random() < .5 else f"{act}, {place}"))
        want.append((kind, action, position))
    style = draw.choice(["- {k}: {v}\n", "{k}: {v}\n", "{n}. {k} - {v}\n", "{k}: {v}. "])
    text = style.format(n=1, k=ego, v=doing) + "".join(style.format(n=j + 2, k=k, v=v) for j, (k, v) in
                                                       enumerate(lines))
    return text.strip(), want


def clauses(draw: random.Random) -> Scene:
    egos = [("the ego", "car"), ("the ego vehicle", "car"), ("our car", "car"), ("the ego truck", "truck"),
            ("the AV", "car"), ("the ego bus", "bus"), ("my van", "car"), ("Ego", "car")]
    ego_acts = [("drives straight", "go_straight"), ("slows down", "go_straight"), ("keeps its lane", "go_straight"),
                ("changes lanes to the left", "change_lane_to_left"), ("brakes to a stop", "stop")]
    acts = [("brakes hard", "stop"), ("stops", "stop"), ("comes to a halt", "stop"), ("keeps going", "go_straight")]
    places = [(" ahead", "front"), (" behind", "back"), (" on the left", "left"), (" on the right", "right"),
              (" in the left lane ahead", "front_left"), (" in the right lane behind", "back_right"),
              (" in front of the ego", "front"), (" ahead in the right lane", "front_right")]
    people = [("a pedestrian", "pedestrian"), ("a child", "pedestrian"), ("a jogger", "pedestrian"),
              ("a cyclist", "cyclist")]
    crossings = [("crosses the road from the right", "front_right"), ("crosses from the left", "front_left"),
                 ("walks across the road in front of the ego", "front")]
    joins = ["{E} {ea} while {A}{p} {a}.", "{E} {ea}. {A}{p} {a}, and {P} {pa}.", "{A}{p} {a} as {E} {ea}.",
             "There is {A}{p} that {a}. {E} {ea}.", "{E} {ea}; {P} {pa} and {A}{p} {a}.",
             "{E} {ea}. Meanwhile {A}{p} {a}.", "{P} {pa} while {E} {ea}.", "{E} {ea}, with {A}{p} that {a}.",
             "Just as {E} {ea}, {A}{p} {a}.", "{A}{p} {a}, so {E} {ea}."]
    (ego, ego_type), (ea, ego_act) = draw.choice(egos), draw.choice(ego_acts)
    (vehicle, kind), (act, action), (place, position) = draw.choice(VEHICLES), draw.choice(acts), draw.choice(places)
    (person, person_type), (crossing, crossing_place) = draw.choice(people), draw.choice(crossings)
    if person_type == "cyclist":
        crossing = crossing.replace("walks", "rides")
    join = draw.choice(joins)
    text = join.format(E=ego, ea=ea, A=vehicle, p=place, a=act, P=person, pa=crossing)
    want = [(ego_type, ego_act, "ego")] + ([(kind, action, position)] if "{A}" in join else [])
    if "{P}" in join:
        want.append((person_type, "cross_the_road", crossing_place))
    return text[0].upper() + text[1:], want


def requests(draw: random.Random) -> Scene:
    acts = [("brakes hard", "brake hard", "braking hard", "stop"), ("stops", "stop", "stopping", "stop"),
            ("drives straight on", "drive straight on", "driving straight on", "go_straight")]
    places = [(" ahead", "front"), (" behind", "back"), (" in the left lane ahead", "front_left"),
              (" in front of the ego", "front"), (" behind the ego", "back")]
    ego_acts = [("drives straight", "drive straight", "driving straight", "go_straight"),
                ("changes lanes to the left", "change lanes to the left", "changing lanes to the left",
                 "change_lane_to_left"), ("stops", "stop", "stopping", "stop")]
    forms = ["Create a scenario where the ego {ef} and {A}{p} {af}.", "I want {A}{p} to {ai} while the ego {ef}.",
             "Please add {A}{p} that {af}; the ego should {ei}.", "Make the ego {ei}. Put {A}{p}, {ag}.",
             "Can you make a test where the ego {ef} with {A}{p} {ag}?", "Have {A}{p} {ai} as the ego {ef}.",
             "Test case: ego {eg}, {A}{p} {ag}."]
    (vehicle, kind), (af, ai, ag, action), (place, position) = draw.choice(VEHICLES), draw.choice(acts), \
        draw.choice(places)
    ef, ei, eg, ego_act = draw.choice(ego_acts)
    text = draw.choice(forms).format(A=vehicle, p=place, af=af, ai=ai, ag=ag, ef=ef, ei=ei, eg=eg)
    return text, [(kind, action, position), ("car", ego_act, "ego")]


def junctions(draw: random.Random) -> Scene:
    ego_acts = [("turns left at the intersection", "turn_left"), ("turns right at the junction", "turn_right"),
                ("goes straight through the crossroads", "go_straight")]
    roads = [("from the opposite direction", "road_of_straight"), ("coming the other way", "road_of_straight"),
             ("from the left", "road_of_left_turn"), ("from the right", "road_of_right_turn"),
             ("from the road on the left", "road_of_left_turn"), ("from the road on the right", "road_of_right_turn")]
    acts = [("goes straight", "go_straight"), ("turns left", "turn_left"), ("turns right", "turn_right")]
    forms = ["The ego {ea} while {A} {w} {a}.", "The ego {ea}. {A} {w} {a}.", "{A} {w} {a} as the ego {ea}."]
    (ea, ego_act), (vehicle, kind), (where, position), (a, action) = draw.choice(ego_acts), draw.choice(VEHICLES), \
        draw.choice(roads), draw.choice(acts)
    text = draw.choice(forms).format(ea=ea, A=vehicle, w=where, a=a)
    return text[0].upper() + text[1:], [("car", ego_act, "ego"), (kind, action, position)]


def positions(draw: random.Random) -> Scene:
    places = [("ahead on the left", "front_left"), ("behind on the right", "back_right"),
              ("in the left lane ahead", "front_left"), ("to the ego's front left", "front_left"),
              ("at the ego's right rear", "back_right"), ("on the right front", "front_right"),
              ("in the lane to the left, slightly ahead", "front_left"), ("level with the ego on the left", "left"),
              ("alongside on the right", "right"), ("directly ahead", "front"), ("right behind the ego", "back"),
              ("in the ego's blind spot on the left", "back_left"), ("behind and to the right", "back_right"),
              ("30 m behind in the right lane", "back_right"), ("in the fast lane behind", "back_left")]
    (place, position), (vehicle, kind) = draw.choice(places), draw.choice(VEHICLES)
    return f"On a three-lane road, {vehicle} is {place}, driving straight.", [("car", "go_straight", "ego"),
                                                                            (kind, "go_straight", position)]


def names(draw: random.Random) -> Scene:
    users = [("a hatchback", "car"), ("a camper van", "car"), ("a quad bike", "motorcycle"), ("a tractor", "truck"),
             ("a bin lorry", "truck"), ("a tow truck", "truck"), ("a fuel tanker", "truck"), ("a limo", "car"),
             ("a police motorcycle", "police"), ("a fire engine", "firetruck"), ("a squad car", "police"),
             ("an e-bike rider", "cyclist"), ("a cargo bike", "cyclist"), ("a jogger", "pedestrian"),
             ("a wheelchair user", "pedestrian"), ("a man pushing a pram", "pedestrian"), ("a minicab", "car"),
             ("a double-decker", "bus"), ("a coach", "bus"), ("an articulated lorry", "truck"), ("a moped", "motorcycle"),
             ("a school bus", "bus"), ("an 18-wheeler", "truck"), ("a semi", "truck"), ("a digger", "truck")]
    (user, kind) = draw.choice(users)
    return f"The ego drives straight and {user} ahead stops.", [("car", "go_straight", "ego"), (kind, "stop", "front")]


def verbs(draw: random.Random) -> Scene:
    stopping = ["comes to a halt", "is stationary", "has stopped", "sits idling", "is stuck in traffic", "halts",
                "stops dead", "is at a standstill", "remains stopped", "brakes to a halt", "is queuing"]
    going = ["carries on", "continues", "proceeds", "keeps going", "is travelling", "cruises along", "drives on",
             "keeps its speed", "carried straight on", "is moving"]
    action = draw.choice(["stop", "go_straight"])
    verb = draw.choice(stopping if action == "stop" else going)
    subject = draw.choice(["A truck ahead of the ego", "The car in front", "A van ahead of me"])
    kind = "truck" if "truck" in subject else "car"
    return f"{subject} {verb}.", [("car", "go_straight", "ego"), (kind, action, "front")]


def rementions(draw: random.Random) -> Scene:
    """An account that names one vehicle, then names it again the ways reports and claims do."""
    vehicles = [("a silver Honda Civic", "car", "Honda"), ("a white Transit van", "car", "van"),
                ("a black SUV", "car", "SUV"), ("a taxi", "car", "taxi"), ("an articulated lorry", "truck", "lorry"),
                ("a box truck", "truck", "truck"), ("a delivery van", "car", "van"), ("a sedan", "car", "sedan")]
    firsts = ["{A} pulled out of a side road on my left", "{A} came the other way", "{A} was ahead of me in my lane",
              "{A} overtook me on the right", "{A} was parked on my left", "there was {A} behind me"]
    again = ["the other driver", "the other vehicle", "the third party", "the offending vehicle", "the culprit",
             "the vehicle in question", "the {n} driver", "the driver of the {n}", "the {n}'s driver", "this guy",
             "that idiot", "the {n}", "it", "the driver", "the guy", "the woman driving it", "the man driving the {n}"]
    thens = ["{S} didn't indicate", "{S} never looked", "{S} braked hard", "{S} kept going", "{S} drove off",
             "I honked but {S} ignored me"]
    vehicle, kind, noun = draw.choice(vehicles)
    said = [draw.choice(firsts).format(A=vehicle)] + [draw.choice(thens).format(S=draw.choice(again).format(n=noun))
                                                      for _ in range(2)]
    text = "I was driving to work on Tuesday morning. " + ". ".join(x[0].upper() + x[1:] for x in said) + "."
    return text, Counter({("ego", "car"): 1, kind: 1})


def asides(draw: random.Random) -> Scene:
    """A plain scene and a sentence that names people or vehicles who are not in it."""
    scenes = [("A van pulls out of a side road on my left", "car"), ("A lorry ahead of me brakes hard", "truck"),
              ("A cyclist crosses in front of me from the right", "cyclist"), ("A bus comes the other way", "bus")]
    aside = ["My wife was in the passenger seat", "The examiner marked it as a fault", "The safety driver took over",
             "A witness filmed it on her phone", "Pedestrians in this town never use the crossing",
             "Truck drivers have huge blind spots", "Everyone on the bus was fine", "The traffic warden saw nothing",
             "Nobody was hurt", "There were no other cars", "Someone should fix that junction",
             "The workers at the depot say it happens daily", "The kids in the back didn't notice",
             "Cyclists get hurt like this all the time", "The police officer who took the report agreed",
             "My son asked why the man was so angry"]
    (scene, kind), extra = draw.choice(scenes), draw.choice(aside)
    parts = ["I was driving through town", scene, extra] if draw.random() < .5 else \
        ["I was driving through town", extra, scene]
    return ". ".join(parts) + ".", Counter({("ego", "car"): 1, kind: 1})


def sides(draw: random.Random) -> Scene:
    """A turn into a road or a lane change, each said many ways, to either side."""
    side = draw.choice(["left", "right"])
    turns = ["turns {} into", "turned {} onto", "is turning {} into", "makes a {} into", "hangs a {} into",
             "swings {} into", "bears {} into", "takes a {} into"]
    roads = ["the side road", "the main road", "a car park", "the side street", "the high street"]
    lanes = ["moves into the {} lane", "changes lanes to the {}", "pulls out to the {}", "shifts over a lane to the {}",
             "merges {}", "slides into the lane on its {}", "moves over to the {}", "drifts into the {} lane"]
    if draw.random() < .5:
        return f"The ego {draw.choice(turns).format(side)} {draw.choice(roads)}.", [("car", f"turn_{side}", "ego")]
    return f"The ego {draw.choice(lanes).format(side)}.", [("car", f"change_lane_to_{side}", "ego")]


def around(draw: random.Random) -> Scene:
    """Others moving round the ego as drivers tell it: out from the kerb, out to pass, towards it, beside it, parked
    with something of theirs going."""
    noun, kind = draw.choice([("car", "car"), ("van", "car"), ("taxi", "car"), ("pickup", "car"), ("truck", "truck"),
                              ("lorry", "truck"), ("bus", "bus")])
    side = draw.choice(["left", "right"])
    opening = draw.choice(["", "I was driving through town. ", "On the way home, ", "The ego is on a two-lane road. "])
    thing = draw.choice(["hazards going", "engine running", "hazard lights flashing", "indicator going"])
    told = [
        (f"a {noun} pulled out from the kerb ahead of me.", (kind, "change_lane_to_left", "front_right")),
        (f"a parked {noun} pulled out in front of me.", (kind, "change_lane_to_left", "front_right")),
        (f"a {noun} pulled out to overtake me.", (kind, "change_lane_to_left", "back")),
        (f"the {noun} behind me pulled out round me.", (kind, "change_lane_to_left", "back")),
        (f"a {noun} coming towards me turned {side} at the junction.", (kind, f"turn_{side}", "road_of_straight")),
        (f"the {noun} opposite me at the junction turned {side}.", (kind, f"turn_{side}", "road_of_straight")),
        (f"a {noun} was parked ahead with its {thing}.", (kind, "stop", "front")),
        (f"a {noun} was sitting right next to me on my {side}.", (kind, "go_straight", side)),
        (f"a {noun} was sitting on my tail.", (kind, "go_straight", "back")),
    ]
    text, agent = draw.choice(told)
    return opening + text[0].upper() + text[1:] if not opening or opening.endswith(". ") else opening + text, \
        [("car", "go_straight", "ego"), agent]


FAMILIES: dict[str, Callable[[random.Random], Scene]] = {
    "terse lists": terse_lists, "notes": notes, "clauses": clauses, "requests": requests, "junctions": junctions,
    "positions": positions, "road users' names": names, "verbs of stopping and going": verbs,
    "vehicles named again": rementions, "asides naming no one": asides, "sides of turns, lanes": sides,
    "others round the ego": around}


def read(text: str) -> list[Key]:
    return sorted(agent_keys(lower_prompt(text, "offline").scenario).elements())


def wrong(scene: Scene) -> tuple[str, object, object] | None:
    text, want = scene
    try:
        got = read(text)
    except Exception as e:  # noqa: BLE001 - a refusal is a reading too
        return text, want, f"refused: {e}"
    if isinstance(want, Counter):
        by_type = Counter(("ego", t) if where == "ego" else t for t, _, where in got)
        return None if by_type == want else (text, dict(want), got)
    return None if got == sorted(want) else (text, sorted(want), got)


def scenes(family: Callable[[random.Random], Scene], n: int, seed: int) -> Iterator[Scene]:
    draw = random.Random(seed)
    for _ in range(n):
        yield family(draw)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=300, help="scenes a family")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--show", type=int, default=3, help="wrong readings to print a family")
    args = parser.parse_args()
    total = bad = 0
    for name, family in FAMILIES.items():
        misses = [m for m in map(wrong, scenes(family, args.n, args.seed)) if m is not None]
        total, bad = total + args.n, bad + len(misses)
        print(f"{name:28} {len(misses):4d} of {args.n} read wrong")
        for text, want, got in misses[:args.show]:
            print(f"    {text!r}\n      want {want}\n      read {got}")
    print(f"all families: {bad} of {total} read wrong ({bad / total:.1%})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
