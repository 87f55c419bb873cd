"""The paper's quality figures (TTSG appendix, "Metrics Definition"), computed on scenarios.

AA, agent accuracy: agents matched on (type, action, position) / max(#gold, #predicted).
RA, road accuracy: road properties matched (lanes, junction, required and forbidden signals and objects)
/ max(#gold, #predicted).
"""

from __future__ import annotations

from collections import Counter

from ttsgc.scenario import Scenario


def agent_keys(s: Scenario) -> Counter:
    return Counter((a.type, a.action, a.relative_to_ego or "ego") for a in s.agents())


def road_keys(s: Scenario) -> set[tuple]:
    r = s.road
    keys = {("lanes", r.lanes)}
    if r.junction is not None:
        keys.add(("junction", r.junction))
    keys |= {("has", w) for w in r.required_signals + r.required_objects}
    keys |= {("without", w) for w in r.without_signals + r.without_objects}
    return keys


def agent_accuracy(gold: Scenario, predicted: Scenario) -> float:
    g, p = agent_keys(gold), agent_keys(predicted)
    return sum((g & p).values()) / max(sum(g.values()), sum(p.values()), 1)


def road_accuracy(gold: Scenario, predicted: Scenario) -> float:
    g, p = road_keys(gold), road_keys(predicted)
    return len(g & p) / max(len(g), len(p), 1)
