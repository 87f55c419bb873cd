"""The parameter mechanism of OpenSCENARIO: expressions, declarations and their scopes, catalogs, and every
error with its file and line."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from lxml import etree

from ttsgc.simulate.resolve import CatalogError, ParameterError, Parameter, Scope, evaluate, resolve

FOREIGN = Path(__file__).parent / "foreign"


def scope(**values) -> Scope:
    s = Scope()
    for name, value in values.items():
        kind = {bool: "boolean", int: "int", float: "double", str: "string"}[type(value)]
        s.own[name] = Parameter(name, kind, value, "test:1")
    return s


@pytest.mark.parametrize("text, expected", [
    ("1 + 2 * 3", 7), ("(1 + 2) * 3", 9), ("10 - 4 - 3", 3), ("-2 * -3", 6), ("7 % 4", 3), ("-7 % 4", -3),
    ("$Speed / 3.6", 20), ("round(2.5)", 3), ("round(-2.5)", -3), ("floor(-1.5)", -2), ("ceil(1.2)", 2),
    ("sqrt(16)", 4), ("pow(2, 10)", 1024), ("min(3, $N)", 3), ("max(3, $N)", 4), ("1.5e2", 150),
    ("not $Flag", False), ("$Flag and true", True), ("false or $Flag", True), ("not true or true", True),
])
def test_expressions(text, expected):
    assert evaluate(text, scope(Speed=72.0, N=4, Flag=True), "f:1") == pytest.approx(expected)


@pytest.mark.parametrize("text, message", [
    ("$Nope + 1", "unknown parameter $Nope"),
    ("$Spede * 2", "did you mean $Speed?"),
    ("1 / 0", "division by zero"),
    ("5 % (2 - 2)", "modulo by zero"),
    ("$Name + 1", "$Name is a string parameter"),
    ("$Flag + 1", "a boolean where a number is needed"),
    ("not 3", "where a boolean (true or false) is needed"),
    ("1 +", "bad expression"),
    ("1 < 2", "bad expression"),
    ("speed * 2", "bad expression"),
    ("pow(10, 400)", "no real value in range"),
    ("1e308 * 10", "out of the range of a double"),
    ("sqrt(-1)", "sqrt of the negative number -1"),
    ("pow(2)", "pow takes 2 arguments, not 1"),
])
def test_expression_errors(text, message):
    with pytest.raises(ParameterError, match="^f:7: .*" + message.replace("$", r"\$").replace("(", r"\(")
                       .replace(")", r"\)").replace("?", r"\?")):
        evaluate(text, scope(Speed=72.0, Name="car", Flag=True), "f:7")


def test_a_deeply_nested_expression_is_an_error_not_a_crash():
    with pytest.raises(ParameterError):
        evaluate("-" * 1500 + "1", Scope(), "f:1")


def document(body: str, version: int = 2, declarations: str = "") -> str:
    return (f'<?xml version="1.0"?>\n<OpenSCENARIO>\n<FileHeader revMajor="1" revMinor="{version}" '
            f'date="2026-01-01T00:00:00" description="d" author="a"/>\n'
            f'<ParameterDeclarations>\n{declarations}</ParameterDeclarations>\n{body}</OpenSCENARIO>\n')


def declaration(name: str, kind: str, value: str) -> str:
    return f'<ParameterDeclaration name="{name}" parameterType="{kind}" value="{value}"/>\n'


def resolved(tmp_path: Path, text: str):
    path = tmp_path / "scene.xosc"
    path.write_text(text)
    return resolve(etree.parse(str(path)).getroot(), path)


def test_references_and_expressions_are_written_out_with_the_attribute_type(tmp_path):
    text = document('<Entities><Foo s="$S" laneId="$Lane" count="${$Lane * -2}" v="${$S / 4}"/></Entities>\n',
                    declarations=declaration("S", "double", "10") + declaration("Lane", "int", "-3"))
    out = resolved(tmp_path, text)
    foo = out.root.find("Entities/Foo")
    assert (foo.get("s"), foo.get("laneId"), foo.get("count"), foo.get("v")) == ("10", "-3", "6", "2.5")
    assert out.root.find("ParameterDeclarations/ParameterDeclaration").get("value") == "10"


def test_a_declaration_may_use_the_ones_before_it_and_inner_scopes_hide_outer_ones(tmp_path):
    story = ('<Storyboard><Story name="s"><ParameterDeclarations>' + declaration("Speed", "double", "${$Speed * 2}") +
             '</ParameterDeclarations><Act name="$Name"><X speed="$Speed"/></Act></Story>'
             '<Other speed="$Speed"/></Storyboard>\n')
    out = resolved(tmp_path, document(story, declarations=declaration("Speed", "double", "10") +
                                      declaration("Name", "string", "act_${1}")))
    assert out.root.find("Storyboard/Story/Act/X").get("speed") == "20"
    assert out.root.find("Storyboard/Other").get("speed") == "10"


@pytest.mark.parametrize("kind, value, message", [
    ("double", "fast", "declared double but its value is 'fast'"),
    ("double", "nan", "declared double but its value is 'nan'"),
    ("double", "1e999", "out of the range of a double"),
    ("int", "1.5", r"declared int \(-2147483648..2147483647\) but its value is '1.5'"),
    ("unsignedInt", "-1", "declared unsignedInt"),
    ("unsignedShort", "70000", "declared unsignedShort"),
    ("boolean", "yes", "declared boolean but its value is 'yes'"),
    ("dateTime", "tomorrow", "declared dateTime"),
    ("float", "1", "unknown parameterType 'float'"),
])
def test_a_value_not_of_its_declared_type_is_an_error_at_its_line(tmp_path, kind, value, message):
    with pytest.raises(ParameterError, match=rf"scene.xosc:5: parameter P.*{message}"):
        resolved(tmp_path, document("", declarations=declaration("P", kind, value)))


def test_1_0_integer_is_int(tmp_path):
    out = resolved(tmp_path, document('<E n="$P"/>\n', version=0, declarations=declaration("P", "integer", "4")))
    assert out.root.find("E").get("n") == "4"


def test_an_expression_into_an_integer_attribute_must_be_whole(tmp_path):
    text = document('<Entities>\n<ManeuverGroup maximumExecutionCount="${5 / 2}"/></Entities>\n')
    with pytest.raises(ParameterError, match=r"scene.xosc:7: .*2.5, not a whole number, for an attribute of type "
                                             r"UnsignedInt"):
        resolved(tmp_path, text)


def test_a_boolean_parameter_in_a_number_attribute_is_a_type_mismatch(tmp_path):
    text = document('<Entities>\n<LanePosition s="$On"/></Entities>\n',
                    declarations=declaration("On", "boolean", "true"))
    with pytest.raises(ParameterError, match=r"scene.xosc:8: LanePosition s '\$On' \(boolean\) gives 'true', not a "
                                             r"number"):
        resolved(tmp_path, text)


def test_an_unknown_reference_names_its_line(tmp_path):
    with pytest.raises(ParameterError, match=r"scene.xosc:7: unknown parameter \$Missing"):
        resolved(tmp_path, document('<Entities>\n<LanePosition s="$Missing"/></Entities>\n'))


def test_constraint_groups_are_enforced(tmp_path):
    constrained = ('<ParameterDeclaration name="V" parameterType="double" value="40"><ConstraintGroup>'
                   '<ValueConstraint rule="lessOrEqual" value="30"/></ConstraintGroup></ParameterDeclaration>\n')
    with pytest.raises(ParameterError, match=r"parameter V = 40 breaks its constraints \(lessOrEqual 30\)"):
        resolved(tmp_path, document("", declarations=constrained))


def test_catalog_entries_are_inlined_with_their_assignments(tmp_path):
    out = resolve(etree.parse(str(FOREIGN / "follow.xosc")).getroot(), FOREIGN / "follow.xosc")
    ego, lead = (out.root.find(f"Entities/ScenarioObject[@name='{n}']/Vehicle") for n in ("Ego", "Lead"))
    assert ego.find("BoundingBox/Dimensions").get("length") == "4.5"
    assert lead.find("BoundingBox/Dimensions").get("length") == "5.2"
    assert lead.find("BoundingBox/Center").get("x") == "1.6"  # 5.2 / 2 - 1, from the entry's own declarations
    target = out.root.find(".//ManeuverGroup/Maneuver//AbsoluteTargetSpeed")
    assert target.get("value") == "15"
    assert out.where(target).startswith(str(FOREIGN / "Catalogs" / "Maneuvers" / "moves.xosc") + ":")
    assert out.root.find(".//CatalogReference") is None


def copy_foreign(tmp_path: Path) -> Path:
    shutil.copytree(FOREIGN, tmp_path / "foreign")
    shutil.copy(Path(__file__).parent.parent / "maps" / "motorway_3lane.xodr", tmp_path / "motorway_3lane.xodr")
    scene = tmp_path / "foreign" / "follow.xosc"
    scene.write_text(scene.read_text().replace("../../maps/motorway_3lane.xodr", "../motorway_3lane.xodr"))
    return scene


def edited(scene: Path, old: str, new: str) -> Path:
    text = scene.read_text()
    assert old in text
    scene.write_text(text.replace(old, new, 1))
    return scene


def test_a_missing_catalog_folder_is_named(tmp_path):
    scene = edited(copy_foreign(tmp_path), 'path="Catalogs/Vehicles"', 'path="Catalogs/Cars"')
    with pytest.raises(CatalogError, match=r"follow.xosc:\d+: catalog 'Cars' not found: .*Catalogs/Cars \(does not "
                                           r"exist, named at .*follow.xosc:16\)"):
        resolve(etree.parse(str(scene)).getroot(), scene)


def test_an_unknown_entry_and_an_undeclared_assignment_are_errors(tmp_path):
    scene = edited(copy_foreign(tmp_path), 'value="sedan"', 'value="sedam"')
    with pytest.raises(CatalogError, match=r"catalog Cars has no entry 'sedam'; did you mean sedan\?"):
        resolve(etree.parse(str(scene)).getroot(), scene)
    scene = edited(copy_foreign(tmp_path / "again"), 'parameterRef="Length"', 'parameterRef="Lenght"')
    with pytest.raises(CatalogError, match=r"follow.xosc:32: the catalog entry Vehicle 'sedan' declares no parameter "
                                           r"'Lenght' \(it declares HalfLength, Length\)"):
        resolve(etree.parse(str(scene)).getroot(), scene)


def test_a_catalog_error_names_the_catalog_file(tmp_path):
    scene = copy_foreign(tmp_path)
    edited(scene.parent / "Catalogs" / "Vehicles" / "cars.xosc", 'length="$Length"', 'length="$Lenth"')
    with pytest.raises(ParameterError, match=r"cars.xosc:12: unknown parameter \$Lenth; did you mean \$Length\?"):
        resolve(etree.parse(str(scene)).getroot(), scene)

EXPRESSION_TEXT = st.lists(st.sampled_from(["1", "0", "2.5", "1e308", "$N", "$Flag", "$Name", "$Nope", "+", "-",
                                            "*", "/", "%", "(", ")", ",", "and", "or", "not", "true", "round(",
                                            "pow(", "sqrt(", "min(", " ", "pi", "<", "1e999"]),
                           max_size=25).map("".join)


@settings(max_examples=400, deadline=None)
@given(EXPRESSION_TEXT)
def test_any_expression_gives_a_finite_value_or_a_parameter_error(text):
    try:
        value = evaluate(text, scope(N=4, Flag=True, Name="car"), "f:1")
    except ParameterError as exc:
        assert str(exc).startswith("f:1: ")
    else:
        assert isinstance(value, bool) or value == value and abs(value) < float("inf")


def test_the_files_parameters_can_be_assigned_from_outside(tmp_path):
    text = document('<E s="$S" n="$N"/>\n', declarations=declaration("S", "double", "10") +
                    declaration("N", "int", "${$S / 5}"))
    out = resolved_with(tmp_path, text, {"S": "25"})
    assert (out.root.find("E").get("s"), out.root.find("E").get("n")) == ("25", "5")
    with pytest.raises(ParameterError, match=r"declared double but its value is 'fast'"):
        resolved_with(tmp_path, text, {"S": "fast"})
    with pytest.raises(ParameterError, match=r"the file declares no parameter Speed to assign \(it declares N, S\)"):
        resolved_with(tmp_path, text, {"Speed": "3"})


def resolved_with(tmp_path: Path, text: str, assign: dict[str, str]):
    path = tmp_path / "scene.xosc"
    path.write_text(text)
    return resolve(etree.parse(str(path)).getroot(), path, assign=assign)
