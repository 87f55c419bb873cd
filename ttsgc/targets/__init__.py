"""Targets: which player a compiled file is written for. `generic` is standard OpenSCENARIO as the emitter
writes it; `esmini` is the same file, held against esmini's coverage; `carla` is the 1.0 subset CARLA
ScenarioRunner reads (ttsgc/targets/carla.py). A scene is always proven on its generic file; the target's file
is made from it afterwards, and anything the target cannot express is an error before anything is written."""

from __future__ import annotations

from ttsgc.binding.scene import BoundScene
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.scenario import Scenario

TARGETS = ("generic", "esmini", "carla")
GENERIC = "generic"
CARLA_VERSION = "1.0"


class TargetError(TtsgcError):
    """The scene needs what the target player cannot express."""

    exit_code = ExitCode.UNSUPPORTED_BY_TARGET


def choose_version(target: str, version: str | None, default: str) -> str:
    """The OpenSCENARIO version to write: the target's own for carla, else the one asked for."""
    if target not in TARGETS:
        raise TtsgcError(f"unknown target '{target}'; choose one of {', '.join(TARGETS)}")
    if target == "carla":
        if version not in (None, CARLA_VERSION):
            raise TargetError(f"--target carla writes OpenSCENARIO {CARLA_VERSION}, the only version CARLA "
                              f"ScenarioRunner reads; --osc-version {version} cannot be written for it")
        return CARLA_VERSION
    return version or default


def written_version(target: str, version: str) -> str:
    """The version a pipeline call writes: carla's own whatever the caller's default (the command line refuses
    an explicit other version, choose_version)."""
    return CARLA_VERSION if target == "carla" else version


def check_scenario(scenario: Scenario, target: str) -> None:
    """Refuse, before any work, a scene that needs what the target cannot express."""
    if target not in TARGETS:
        raise TtsgcError(f"unknown target '{target}'; choose one of {', '.join(TARGETS)}")
    if target == "carla":
        from ttsgc.targets import carla

        problems = carla.needs(scenario)
        if problems:
            raise TargetError(f"scenario '{scenario.name}' cannot be written for CARLA ScenarioRunner: "
                              + "; ".join(problems))


def retarget(generic: bytes, scene: BoundScene, target: str) -> bytes:
    """The file for the target, made from the scene's generic file."""
    if target == "carla":
        from ttsgc.emit.xosc import validate
        from ttsgc.targets import carla

        data, left = carla.adapt(generic, scene)
        if left:
            raise TargetError(f"scenario '{scene.scenario.name}' needs what CARLA ScenarioRunner does not read: "
                              + "; ".join(left))
        validate(data, CARLA_VERSION)
        return data
    if target == "esmini":
        from lxml import etree

        from ttsgc.targets.coverage import errors, lint_tree

        left = [f"line {f.line}: {f.what}" for f in errors(lint_tree(etree.fromstring(generic), "esmini"))]
        if left:
            raise TargetError(f"scenario '{scene.scenario.name}' needs what esmini does not read: "
                              + "; ".join(left))
    return generic
