"""The standard's parameter mechanism, applied to a parsed .xosc before anything reads it: parameter
declarations at every level that has them (the file, storyboard elements, catalog entries), `$name`
references and `${...}` expressions in attribute values, and catalog references replaced by their entries
with the reference's parameter assignments. What comes out is the same document with every value written
out, so a reader needs to know nothing of parameters or catalogs.

Scoping follows the standard: a declaration is seen by the element that declares it and everything inside
it, an inner declaration hides an outer one of the same name, and a catalog entry sees only its own
declarations (with the values its reference assigns). Declarations are read in order, so a value may use
the ones declared before it.

scenariogeneration has an .xosc parser (xosc.ParseOpenScenario, CatalogLoader), but it reads with
xml.etree (no line numbers), keeps `$name` and `${...}` as text rather than resolving them, and builds its
own object model; ttsgc needs the resolved document with every element's file and line for its messages,
so the mechanism is written here over lxml.
"""

from __future__ import annotations

import copy
import difflib
import math
import re
from dataclasses import dataclass, field
from datetime import datetime
from functools import cache
from pathlib import Path

from lark import Lark, Tree
from lark.exceptions import LarkError, UnexpectedInput
from lxml import etree

from ttsgc.files import real_path
from ttsgc.xsd import (INTEGER_TYPES, NUMERIC_TYPES, XoscFileError, attribute_types, errors,
                                         version_of)

REFERENCE = re.compile(r"\$([A-Za-z_][A-Za-z0-9_]*)")
EXPRESSION = re.compile(r"\$\{(.*)\}", re.DOTALL)
DOUBLE = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?")
INTEGER = re.compile(r"[+-]?\d+")
INTEGER_RANGES = {"int": (-2**31, 2**31 - 1), "unsignedInt": (0, 2**32 - 1), "unsignedShort": (0, 2**16 - 1)}
PARAMETER_TYPES = ("int", "double", "string", "boolean", "unsignedInt", "unsignedShort", "dateTime")
NAME_ATTRIBUTES = {("ParameterAssignment", "parameterRef"), ("ParameterSetAction", "parameterRef"),
                   ("ParameterModifyAction", "parameterRef"), ("ParameterCondition", "parameterRef"),
                   ("ParameterAction", "parameterRef")}  # they name a parameter; they do not use its value
MAX_EXPRESSION_CHARS = 2000
MAX_CATALOG_DEPTH = 8
CATALOG_TAGS = ("Vehicle", "Pedestrian", "MiscObject", "Controller", "Route", "Trajectory", "Maneuver",
                "Environment")
XML_PARSER = dict(resolve_entities=False, no_network=True, load_dtd=False)


class ParameterError(XoscFileError):
    """An unknown parameter, a value that is not of its type, a bad expression or one that cannot be computed."""


class ExpressionSyntaxError(ParameterError):
    """Text inside `${...}` that the standard's expression grammar does not read."""


class CatalogError(XoscFileError):
    """A catalog or catalog entry that cannot be found or read, or a parameter assignment it does not declare."""


@dataclass(frozen=True)
class Parameter:
    name: str
    type: str  # one of PARAMETER_TYPES
    value: object  # int, float, bool or str (dateTime is kept as written, once checked)
    where: str  # file:line of the declaration


class Scope:
    """The parameters one element sees: its own declarations, then its ancestors' (none for catalog entries)."""

    def __init__(self, parent: Scope | None = None, borrowing: list[str] | None = None):
        self.parent = parent
        self.own: dict[str, Parameter] = {}
        self.borrowing = borrowing  # a catalog entry's scope: lookups past it are noted here

    def lookup(self, name: str) -> Parameter | None:
        scope = self
        while scope is not None:
            if name in scope.own:
                return scope.own[name]
            if scope.borrowing is not None and scope.parent is not None and scope.parent.lookup(name) is not None:
                scope.borrowing.append(f"a catalog entry uses the scenario's parameter ${name}, which it does not "
                                       f"declare (esmini reads it so; the standard does not)")
            scope = scope.parent
        return None

    def names(self) -> list[str]:
        seen, scope = [], self
        while scope is not None:
            seen.extend(n for n in scope.own if n not in seen)
            scope = scope.parent
        return seen


def _unknown(name: str, scope: Scope, where: str) -> ParameterError:
    close = difflib.get_close_matches(name, scope.names(), n=1)
    hint = f"; did you mean ${close[0]}?" if close else (
        f" (declared here: {', '.join('$' + n for n in scope.names())})" if scope.names() else
        " (no parameter is declared where it is used)")
    return ParameterError(f"{where}: unknown parameter ${name}{hint}")


# --- values of a declared type -------------------------------------------------------------------------------

def typed_value(type_name: str, text: str, where: str, what: str) -> object:
    """A parameter's value read as its declared type; a value that is not of that type is an error."""
    type_name = "int" if type_name == "integer" else type_name  # 1.0's name for it, deprecated since 1.1
    if type_name == "double":
        if not DOUBLE.fullmatch(text.strip()):
            raise ParameterError(f"{where}: {what} is declared double but its value is '{text}'")
        value = float(text)
        if not math.isfinite(value):
            raise ParameterError(f"{where}: {what} = '{text}' is out of the range of a double")
        return value
    if type_name in INTEGER_RANGES:
        low, high = INTEGER_RANGES[type_name]
        if not INTEGER.fullmatch(text.strip()) or len(text.strip()) > 12 or not low <= int(text) <= high:
            raise ParameterError(f"{where}: {what} is declared {type_name} ({low}..{high}) but its value is '{text}'")
        return int(text)
    if type_name == "boolean":
        if text.strip() not in ("true", "false"):
            raise ParameterError(f"{where}: {what} is declared boolean but its value is '{text}' (true or false)")
        return text.strip() == "true"
    if type_name == "dateTime":
        try:
            datetime.fromisoformat(text.strip())
        except ValueError:
            raise ParameterError(f"{where}: {what} is declared dateTime but its value is '{text}' "
                                 f"(e.g. 2024-05-01T12:00:00)") from None
        return text
    if type_name == "string":
        return text
    raise ParameterError(f"{where}: {what} has the unknown parameterType '{type_name}' "
                         f"(one of {', '.join(PARAMETER_TYPES)})")


def text_of(value: object, target: str, where: str, what: str) -> str:
    """A value written for an attribute of XSD type `target` (Double, Int, Boolean, String, an enumeration...)."""
    if target in NUMERIC_TYPES:
        if isinstance(value, bool) or isinstance(value, str) and not DOUBLE.fullmatch(value.strip()):
            raise ParameterError(f"{where}: {what} gives '{_plain(value)}', not a number, for an attribute of type "
                                 f"{target}")
        number = float(value)
        if target in INTEGER_TYPES:
            if not number.is_integer():
                raise ParameterError(f"{where}: {what} gives {_plain(value)}, not a whole number, for an attribute "
                                     f"of type {target}")
            return str(int(number))
        return _plain(number)
    if target == "Boolean" and not isinstance(value, bool) and _plain(value) not in ("true", "false"):
        raise ParameterError(f"{where}: {what} gives '{_plain(value)}', not true or false, for a Boolean attribute")
    return _plain(value)


def _plain(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return str(int(value)) if value.is_integer() and abs(value) < 1e15 else repr(value)
    return str(value)


# --- expressions -----------------------------------------------------------------------------------------------

@cache
def _expression_parser() -> Lark:
    from ttsgc.grammars import lalr_parser  # the analysis cached on disk

    return lalr_parser("xosc_expression.lark")


def evaluate(text: str, scope: Scope, where: str, notes: list[str] | None = None) -> float | bool:
    """The value of the expression inside `${...}`; numbers are computed as doubles, as the standard says."""
    if len(text) > MAX_EXPRESSION_CHARS:
        raise ParameterError(f"{where}: the expression is longer than {MAX_EXPRESSION_CHARS} characters")
    try:
        tree = _expression_parser().parse(text)
    except UnexpectedInput as exc:
        at = exc.pos_in_stream if exc.pos_in_stream is not None else 0
        found = f"'{text[at:at + 10]}' at column {exc.column}" if text[at:].strip() else "end"
        raise ExpressionSyntaxError(f"{where}: bad expression '${{{text}}}': unexpected {found} "
                                    f"(operators: + - * / % and or not; functions: round floor "
                                    f"ceil sqrt pow min max; parameters as $name)") from None
    except LarkError as exc:
        raise ExpressionSyntaxError(f"{where}: bad expression '${{{text}}}': {exc}") from None
    try:
        return _Evaluator(scope, where, text, notes if notes is not None else []).value(tree)
    except RecursionError:
        raise ParameterError(f"{where}: the expression '${{{text}}}' is nested too deeply") from None


class _Evaluator:
    def __init__(self, scope: Scope, where: str, text: str, notes: list[str]):
        self.scope, self.where, self.text, self.notes = scope, where, text, notes

    def fail(self, why: str) -> ParameterError:
        return ParameterError(f"{self.where}: in '${{{self.text}}}': {why}")

    def number(self, node) -> float:
        value = self.value(node)
        if isinstance(value, bool):
            raise self.fail("a boolean where a number is needed")
        return value

    def boolean(self, node) -> bool:
        value = self.value(node)
        if not isinstance(value, bool):
            raise self.fail(f"the number {_plain(value)} where a boolean (true or false) is needed")
        return value

    def finite(self, value: float) -> float:
        if not math.isfinite(value):
            raise self.fail("the result is out of the range of a double")
        return value

    def value(self, node) -> float | bool:
        kind = node.data if isinstance(node, Tree) else None
        if kind == "number":
            return self.finite(float(node.children[0]))
        if kind == "pi":
            return math.pi
        if kind == "true":
            return True
        if kind == "false":
            return False
        if kind == "parameter":
            name = str(node.children[0])[1:]
            parameter = self.scope.lookup(name)
            if parameter is None:
                raise _unknown(name, self.scope, self.where)
            if parameter.type == "boolean":
                return parameter.value
            if parameter.type == "string" and DOUBLE.fullmatch(parameter.value.strip()):
                self.notes.append(f"{self.where}: the string parameter ${name} is used as a number in "
                                  f"'${{{self.text}}}' (esmini reads it so; the standard wants a numeric type)")
                return self.finite(float(parameter.value))
            if parameter.type in ("string", "dateTime"):
                raise self.fail(f"${name} is a {parameter.type} parameter ('{parameter.value}'); expressions take "
                                f"numbers and booleans")
            return float(parameter.value)
        if kind == "negate":
            return -self.number(node.children[0])
        if kind == "not_op":
            return not self.boolean(node.children[0])
        if kind in ("and_op", "or_op"):
            left, right = self.boolean(node.children[0]), self.boolean(node.children[1])
            return (left and right) if kind == "and_op" else (left or right)
        if kind == "arithmetic":
            left, op, right = node.children
            a, b = self.number(left), self.number(right)
            if op in ("/", "%") and b == 0:
                raise self.fail("division by zero" if op == "/" else "modulo by zero")
            result = {"+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b, "/": lambda: a / b,
                      "%": lambda: math.fmod(a, b)}[str(op)]()
            return self.finite(result)
        if kind == "call":
            return self.call(str(node.children[0]), [self.number(c) for c in node.children[1:]])
        raise self.fail(f"cannot evaluate {node}")  # the grammar has no other node

    def call(self, function: str, args: list[float]) -> float:
        arity = {"round": 1, "floor": 1, "ceil": 1, "sqrt": 1, "pow": 2, "min": 2, "max": 2}[function]
        if len(args) != arity:
            raise self.fail(f"{function} takes {arity} argument{'s' if arity > 1 else ''}, not {len(args)}")
        x = args[0]
        if function == "round":  # halves away from zero
            return math.copysign(math.floor(abs(x) + 0.5), x)
        if function == "floor":
            return float(math.floor(x))
        if function == "ceil":
            return float(math.ceil(x))
        if function == "sqrt":
            if x < 0:
                raise self.fail(f"sqrt of the negative number {_plain(x)}")
            return math.sqrt(x)
        if function == "pow":
            try:
                return self.finite(math.pow(x, args[1]))
            except (OverflowError, ValueError):
                raise self.fail(f"pow({_plain(x)}, {_plain(args[1])}) has no real value in range") from None
        return min(args) if function == "min" else max(args)


# --- the document ---------------------------------------------------------------------------------------------

@dataclass
class Resolved:
    """The document with parameters applied and catalog entries in place of their references."""

    root: etree._Element
    path: Path
    version: str
    notes: list[str] = field(default_factory=list)  # what was read leniently, in words
    origins: dict = field(default_factory=dict)  # a copied catalog entry -> the catalog file it came from
    written: dict = field(default_factory=dict)  # (element, attribute) -> the text it had before resolution

    def where(self, element) -> str:
        """file:line of an element, in the scenario or in the catalog its entry came from."""
        for node in [element, *element.iterancestors()]:
            if node in self.origins:
                return f"{self.origins[node]}:{element.sourceline}"
        return f"{self.path}:{element.sourceline}"


class _Resolver:
    def __init__(self, resolved: Resolved):
        self.out = resolved
        self.types = attribute_types(resolved.version)
        self.catalog_dirs: list[tuple[Path, str]] | None = None
        self.catalogs: dict[str, dict[str, tuple[etree._Element, Path]]] | None = None
        self.file_scope: Scope | None = None  # the file's own parameters, which esmini lets catalog entries see
        self.overrides: dict[str, tuple[str, str]] = {}  # values assigned to the file's parameters from outside

    def where(self, element) -> str:
        return self.out.where(element)

    def declare(self, declarations, parent: Scope | None, overrides: dict[str, tuple[str, str]] | None = None,
                borrowing: list[str] | None = None) -> Scope:
        scope = Scope(parent, borrowing)
        for declaration in declarations.findall("ParameterDeclaration"):
            where = self.where(declaration)
            name, type_name = declaration.get("name", ""), declaration.get("parameterType", "")
            if not REFERENCE.fullmatch("$" + name):
                raise ParameterError(f"{where}: '{name}' is not a parameter name (letters, digits and _)")
            if name in scope.own:
                self.out.notes.append(f"{where}: parameter {name} is declared a second time in one place (first "
                                      f"at {scope.own[name].where}); the later declaration counts")
            text, source = declaration.get("value", ""), where
            if overrides and name in overrides:
                text, source = overrides[name]
            text = self.substitute_text(text, scope, source, f"the value of {name}", _declared_target(type_name))
            value = typed_value(type_name, text, source, f"parameter {name}")
            self.check_constraints(declaration, name, type_name, value, source)
            declaration.set("value", text)
            scope.own[name] = Parameter(name, type_name, value, where)
        return scope

    def check_constraints(self, declaration, name: str, type_name: str, value, where: str) -> None:
        """1.2+: the value must meet every constraint of at least one ConstraintGroup."""
        groups = declaration.findall("ConstraintGroup")
        if not groups or type_name in ("string", "dateTime", "boolean"):
            return
        compare = {"equalTo": lambda a, b: a == b, "notEqualTo": lambda a, b: a != b,
                   "greaterThan": lambda a, b: a > b, "lessThan": lambda a, b: a < b,
                   "greaterOrEqual": lambda a, b: a >= b, "lessOrEqual": lambda a, b: a <= b}
        for group in groups:
            constraints = group.findall("ValueConstraint")
            if all(compare.get(c.get("rule"), lambda a, b: True)(
                    value, typed_value(type_name, c.get("value", ""), self.where(c), f"a constraint on {name}"))
                   for c in constraints):
                return
        rules = " or ".join(" and ".join(f"{c.get('rule')} {c.get('value')}" for c in g.findall("ValueConstraint"))
                            for g in groups)
        raise ParameterError(f"{where}: parameter {name} = {_plain(value)} breaks its constraints ({rules})")

    def substitute_text(self, text: str, scope: Scope, where: str, what: str, target: str) -> str:
        if not text.startswith("$"):
            return text
        expression = EXPRESSION.fullmatch(text)
        if expression is not None:
            value = evaluate(expression.group(1), scope, where, self.out.notes)
            return text_of(value, target, where, f"{what} '{text}'")
        reference = REFERENCE.fullmatch(text)
        if reference is not None:
            parameter = scope.lookup(reference.group(1))
            if parameter is None:
                raise _unknown(reference.group(1), scope, where)
            return text_of(parameter.value, target, where, f"{what} '{text}' ({parameter.type})")
        return text  # not a reference: the schema says whether the attribute may hold it

    def visit(self, element, scope: Scope, depth: int = 0) -> None:
        declarations = element.find("ParameterDeclarations")
        at_root = element is self.out.root
        if at_root:
            declared = {d.get("name") for d in declarations.iter("ParameterDeclaration")} \
                if declarations is not None else set()
            unknown = sorted(set(self.overrides) - declared)
            if unknown:
                raise ParameterError(f"{self.out.path}: the file declares no parameter {', '.join(unknown)} to "
                                     f"assign (it declares {', '.join(sorted(declared)) or 'none'})")
        if declarations is not None:
            scope = self.declare(declarations, scope, self.overrides if at_root else None)
        if at_root:
            self.file_scope = scope
        self.attributes(element, scope)
        self.children(element, scope, depth)

    def children(self, element, scope: Scope, depth: int) -> None:
        for child in list(element):
            if not isinstance(child.tag, str) or child.tag == "ParameterDeclarations":
                continue
            if child.tag == "CatalogReference":
                self.inline(child, scope, depth)
            else:
                self.visit(child, scope, depth)

    def attributes(self, element, scope: Scope) -> None:
        where = self.where(element)
        for name, text in element.attrib.items():
            if not text.startswith("$"):
                continue
            if (element.tag, name) in NAME_ATTRIBUTES:
                element.set(name, text[1:])
                self.out.notes.append(f"{where}: {element.tag} {name} '{text}' names a parameter with its $ "
                                      f"(esmini reads it so; the standard writes the name alone)")
                continue
            target = self.types.get((element.tag, name), "String")
            try:
                value = self.substitute_text(text, scope, where, f"{element.tag} {name}", target)
            except ExpressionSyntaxError:
                if target == "String" and not _mentions_unknown(text, scope):
                    self.out.notes.append(f"{where}: {element.tag} {name} '{text}' is not an expression the "
                                          f"standard defines; kept as written")
                    continue
                raise
            if value != text:
                self.out.written[(element, name)] = text
                element.set(name, value)

    # --- catalogs --------------------------------------------------------------------------------------------

    def inline(self, reference, scope: Scope, depth: int) -> None:
        """Put a copy of the referenced entry in place of the reference, its parameters assigned."""
        where = self.where(reference)
        if depth >= MAX_CATALOG_DEPTH:
            raise CatalogError(f"{where}: catalog references nest deeper than {MAX_CATALOG_DEPTH} (a cycle?)")
        self.attributes(reference, scope)
        assignments = {}
        for assignment in reference.iterfind("ParameterAssignments/ParameterAssignment"):
            self.attributes(assignment, scope)
            assignments[assignment.get("parameterRef", "")] = (assignment.get("value", ""), self.where(assignment))
        catalog, name = reference.get("catalogName", ""), reference.get("entryName", "")
        entries = self.catalog(catalog, where, name)
        if name not in entries:
            close = difflib.get_close_matches(name, entries, n=1)
            raise CatalogError(f"{where}: catalog {catalog} has no entry '{name}'"
                               f"{'; did you mean ' + close[0] + '?' if close else ''}")
        source, path = entries[name]
        entry = copy.deepcopy(source)
        _drop_comments(entry)
        entry.tail = reference.tail
        reference.getparent().replace(reference, entry)
        self.out.origins[entry] = path
        declarations = entry.find("ParameterDeclarations")
        declared = {d.get("name") for d in declarations.findall("ParameterDeclaration")} \
            if declarations is not None else set()
        for parameter, (_, at) in assignments.items():
            if parameter not in declared:
                raise CatalogError(f"{at}: the catalog entry {entry.tag} '{name}' declares no parameter "
                                   f"'{parameter}'" + (f" (it declares {', '.join(sorted(declared))})"
                                                       if declared else ""))
        borrowing = [] if self.file_scope is not None else None
        entry_scope = self.declare(declarations, self.file_scope, assignments, borrowing) \
            if declarations is not None else Scope(self.file_scope, borrowing)
        self.attributes(entry, entry_scope)
        self.children(entry, entry_scope, depth + 1)
        self.out.notes.extend(f"{where}: {note}" for note in dict.fromkeys(borrowing or []))

    def catalog(self, name: str, where: str, entry: str | None = None) -> dict[str, tuple[etree._Element, Path]]:
        if self.catalogs is None:
            self.catalogs = {}
            self.catalog_dirs = []
            for location in self.out.root.iterfind("CatalogLocations/*/Directory"):
                folder = real_path(self.out.path.parent / location.get("path", ""))
                self.catalog_dirs.append((folder, self.where(location)))
                if folder.is_dir():
                    for file in sorted(folder.glob("*.xosc")):
                        self.read_catalog_file(file)
        if name not in self.catalogs and entry is not None:
            holders = [catalog for catalog, entries in self.catalogs.items() if entry in entries]
            if holders:
                self.out.notes.append(f"{where}: no catalog is named '{name}'; entry '{entry}' was taken from "
                                      f"catalog '{holders[0]}' (esmini reads it so)")
                return self.catalogs[holders[0]]
        if name not in self.catalogs:
            looked = "; ".join(f"{folder} ({'does not exist' if not folder.is_dir() else 'no such catalog'}, "
                               f"named at {at})" for folder, at in self.catalog_dirs) or \
                "the file has no CatalogLocations"
            raise CatalogError(f"{where}: catalog '{name}' not found: {looked}")
        return self.catalogs[name]

    def read_catalog_file(self, file: Path) -> None:
        try:
            root = etree.parse(str(file), etree.XMLParser(**XML_PARSER)).getroot()
        except (OSError, etree.XMLSyntaxError) as exc:
            raise CatalogError(f"{file}: cannot read the catalog: {exc}") from None
        if root.getroottree().docinfo.doctype:
            raise CatalogError(f"{file}: the catalog has a DOCTYPE, which OpenSCENARIO never needs; refused")
        catalog = root.find("Catalog")
        if catalog is None:
            return
        version = version_of(root)
        problems = errors(root.getroottree(), version) if version else [(root.sourceline, "no known FileHeader "
                                                                                         "version", None)]
        if problems:
            raise CatalogError("\n".join(f"{file}:{line}: {message}" for line, message, _ in problems))
        entries = self.catalogs.setdefault(catalog.get("name", ""), {})
        for entry in catalog:
            if isinstance(entry.tag, str) and entry.get("name") is not None:
                entries.setdefault(entry.get("name"), (entry, file))


def _drop_comments(root) -> None:
    """Comments and processing instructions carry no meaning; readers then see elements only."""
    for node in list(root.iter(etree.Comment, etree.ProcessingInstruction)):
        parent = node.getparent()
        if parent is not None:
            if node.tail:  # keep the text layout of the element it sat in
                previous = node.getprevious()
                if previous is not None:
                    previous.tail = (previous.tail or "") + node.tail
                else:
                    parent.text = (parent.text or "") + node.tail
            parent.remove(node)


def _declared_target(type_name: str) -> str:
    return {"double": "Double", "int": "Int", "integer": "Int", "unsignedInt": "UnsignedInt",
            "unsignedShort": "UnsignedShort",
            "boolean": "Boolean"}.get(type_name, "String")


def _mentions_unknown(text: str, scope: Scope) -> bool:
    return any(scope.lookup(name) is None for name in REFERENCE.findall(text))


def resolve(root, path: str | Path, version: str | None = None, assign: dict[str, str] | None = None) -> Resolved:
    """A copy of the document with every parameter, expression and catalog reference written out.

    `assign` gives the file's own (global) parameters other values, as a ParameterValueDistribution's
    parameter sets do; each value is checked against its declared type. Raises ParameterError or
    CatalogError (exit 2) naming the file and line."""
    path = Path(path)
    version = version or version_of(root)
    if version is None:
        raise XoscFileError(f"{path}:{root.sourceline}: no FileHeader with a known OpenSCENARIO version "
                            f"(revMajor 1, revMinor 0 to 3)")
    resolved = Resolved(copy.deepcopy(root), path, version)
    _drop_comments(resolved.root)
    resolver = _Resolver(resolved)
    resolver.overrides = {name: (str(value), f"{path}: the value assigned to {name}")
                          for name, value in (assign or {}).items()}
    resolver.visit(resolved.root, Scope())
    return resolved
