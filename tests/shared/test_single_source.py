"""DESIGN.md invariant 1, enforced on the source: the pipeline evaluates the generated formulas.

* Every function of every ``pipeline/generated/*.py`` module is referenced by code under
  ``pipeline/`` (an import of the module and an attribute reference, or a ``from`` import of
  the function), or is declared audit-only, with a one-line reason, in the generator
  (``GeneratedFunction.audit_only``, rendered as the module's ``AUDIT_ONLY``).
* No module of a paper package (``pipeline/<slug>/``) builds a rotation matrix, a skew
  matrix or an Earth rate of its own. The AST heuristic (:func:`findings`) flags
  - an array built from cos and sin of the same angle: an array display (``np.array``,
    ``np.stack``, ``np.column_stack``, a list or tuple) or the element assignments
    ``m[..., i, j] = ...`` of one array in one function, whose elements use both
    ``cos(a)`` and ``sin(a)`` (directly or through a local name bound to them);
  - a skew matrix: element assignments to ``m[..., i, j]`` and ``m[..., j, i]`` of which
    exactly one is negated, or a 3 x 3 display with zeros on its diagonal;
  - a float literal within 1e-3 of the Earth rate 7.292115e-5 rad/s;
  - a product of an Earth-rate name (``omega_e``, ``omega_ie``, ``w_ie``, ``we``, ``om``...)
    with a cos or sin of an angle (``omega_ie * cos(lat)``);
  - a cross product with an Earth rate (an Earth-rate name, or a call of
    ``frames.earth_rate_*``, among its arguments): a Coriolis, centripetal or
    transport-theorem term typed by hand (``np.cross(2 * w_ie + w_en, v)``,
    ``v_i - np.cross(earth_rate_e(w), r)``);
  - a period from a square root, ``2 pi / sqrt(k)`` (the Schuler period of a generated
    ``oscillation_period`` / ``schuler_period`` typed again);
  - Rodrigues' rotation formula: one sum that uses sin(a) and 1 - cos(a) of one angle
    (``v cos a + (k x v) sin a + k (k . v)(1 - cos a)``).
  Its false positives are declared in :data:`ALLOWED` with the reason.

The heuristic itself is tested on code that re-types those formulas (it must flag them) and
on code that calls the generated functions (it must not).
"""

from __future__ import annotations

import ast
import importlib
import re
from collections import defaultdict

import pytest

from pipeline.registry import ROOT

GENERATED = sorted(
    p for p in (ROOT / "pipeline" / "generated").glob("*.py") if p.stem != "__init__"
)
PAPER_DIRS = sorted(p.parent for p in (ROOT / "pipeline").glob("*/paper.py"))

#: (path relative to the root, enclosing function, rule) -> why the finding is not a re-typed
#: frames formula (or why it stays hand-typed).
ALLOWED: dict[tuple[str, str, str], str] = {
    ("pipeline/north_finding/cli.py", "_parser", "earth_rate_literal"): (
        "the default of the --omega-ie command-line parameter: a value, not a formula"
    ),
    ("pipeline/platform_drift/trajectory.py", "_axes", "cos_sin_array"): (
        "returns the NWU axes (from the generated frames) with cos and sin of the latitude, "
        "computed once per call of the right-hand side: a tuple of values, not a rotation matrix"
    ),
}

_TRIG = {"cos", "sin"}
_EARTH_RATE = re.compile(r"^(omega_?i?e|w_?ie|we|om|omega_earth|earth_rate)$", re.IGNORECASE)
_ARRAY_CALLS = {"array", "stack", "column_stack", "vstack", "hstack", "asarray"}


def _trig(node: ast.AST) -> tuple[str, str] | None:
    """('cos' or 'sin', dump of the argument) if ``node`` is a call of cos/sin, else None."""
    if isinstance(node, ast.Call) and len(node.args) == 1:
        f = node.func
        name = f.attr if isinstance(f, ast.Attribute) else f.id if isinstance(f, ast.Name) else ""
        if name in _TRIG:
            return name, ast.dump(node.args[0])
    return None


def _name(node: ast.AST) -> str:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return ""


class _Scope:
    """Names bound to cos/sin calls in one function (``c, s = np.cos(a), np.sin(a)``)."""

    def __init__(self, fn: ast.AST):
        self.bound: dict[str, tuple[str, str]] = {}
        for node in _walk_scope(fn):
            if not isinstance(node, ast.Assign):
                continue
            for target in node.targets:
                pairs = []
                if isinstance(target, ast.Tuple) and isinstance(node.value, ast.Tuple):
                    pairs = list(zip(target.elts, node.value.elts, strict=False))
                elif isinstance(target, ast.Name):
                    pairs = [(target, node.value)]
                for t, v in pairs:
                    trig = _trig(v)
                    if isinstance(t, ast.Name) and trig:
                        self.bound[t.id] = trig

    def trig_uses(self, node: ast.AST) -> set[tuple[str, str]]:
        uses = set()
        for sub in _walk_scope(node):
            trig = _trig(sub)
            if trig:
                uses.add(trig)
            elif isinstance(sub, ast.Name) and sub.id in self.bound:
                uses.add(self.bound[sub.id])
        return uses


def _factors(node: ast.AST) -> list[ast.AST]:
    """The factors of a product (or quotient) chain: ``a * b / c * -d`` -> [a, b, c, d]."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult | ast.Div):
        return _factors(node.left) + _factors(node.right)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return _factors(node.operand)
    return [node]


def _has_earth_rate(node: ast.AST) -> bool:
    """Whether ``node`` mentions an Earth-rate name or calls an ``earth_rate_*`` function."""
    for sub in ast.walk(node):
        if isinstance(sub, ast.Name | ast.Attribute) and _EARTH_RATE.match(_name(sub)):
            return True
        if isinstance(sub, ast.Call) and _name(sub.func).startswith("earth_rate"):
            return True
    return False


def _cos_and_sin_of_one_angle(uses: set[tuple[str, str]]) -> bool:
    return bool({a for f, a in uses if f == "cos"} & {a for f, a in uses if f == "sin"})


def _element_index(target: ast.AST) -> tuple[str, int, int] | None:
    """(array name, i, j) of an assignment target ``m[..., i, j]`` with constant i, j."""
    if not (isinstance(target, ast.Subscript) and isinstance(target.value, ast.Name)):
        return None
    idx = target.slice
    elts = idx.elts if isinstance(idx, ast.Tuple) else [idx]
    if len(elts) < 2:
        return None
    i, j = elts[-2], elts[-1]
    if isinstance(i, ast.Constant) and isinstance(j, ast.Constant):
        if isinstance(i.value, int) and isinstance(j.value, int):
            return target.value.id, i.value, j.value
    return None


def _functions(tree: ast.Module):
    yield "<module>", tree
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            yield node.name, node


def _walk_scope(scope: ast.AST):
    """Nodes of one scope: like ast.walk, but not into nested function definitions."""
    todo = [scope]
    while todo:
        node = todo.pop()
        yield node
        for child in ast.iter_child_nodes(node):
            if not isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
                todo.append(child)


def _unpacked_values(tree: ast.AST) -> set[int]:
    """ids of the tuples on the right of ``a, b = x, y`` (bindings, not arrays)."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Tuple):
            if any(isinstance(t, ast.Tuple) for t in node.targets):
                out.add(id(node.value))
    return out


def findings(source: str) -> set[tuple[str, str, int]]:
    """(enclosing function, rule, line) of every place ``source`` builds a frames formula."""
    tree = ast.parse(source)
    unpacked = _unpacked_values(tree)
    found: set[tuple[str, str, int]] = set()
    for fname, fn in _functions(tree):
        scope = _Scope(fn)
        elements: dict[str, list[tuple[int, int, ast.AST, int]]] = defaultdict(list)
        for node in _walk_scope(fn):
            # array displays of cos and sin of one angle; 3 x 3 displays with a zero diagonal
            display = None
            if isinstance(node, ast.Call) and _name(node.func) in _ARRAY_CALLS and node.args:
                display = node.args[0]
            elif isinstance(node, ast.List | ast.Tuple) and len(node.elts) >= 2:
                skip = id(node) in unpacked or isinstance(node.ctx, ast.Store)
                display = None if skip else node
            if display is not None and isinstance(display, ast.List | ast.Tuple):
                if _cos_and_sin_of_one_angle(scope.trig_uses(display)):
                    found.add((fname, "cos_sin_array", node.lineno))
                rows = display.elts
                if len(rows) == 3 and all(
                    isinstance(r, ast.List | ast.Tuple) and len(r.elts) == 3 for r in rows
                ):
                    diag = [rows[k].elts[k] for k in range(3)]
                    off = [rows[a].elts[b] for a in range(3) for b in range(3) if a != b]
                    if all(isinstance(d, ast.Constant) and d.value == 0 for d in diag) and not all(
                        isinstance(o, ast.Constant) for o in off
                    ):
                        found.add((fname, "skew", node.lineno))
            # element assignments m[..., i, j] = value
            if isinstance(node, ast.Assign):
                for target in node.targets:
                    pairs = []
                    if isinstance(target, ast.Tuple) and isinstance(node.value, ast.Tuple):
                        pairs = list(zip(target.elts, node.value.elts, strict=False))
                    else:
                        pairs = [(target, node.value)]
                    for t, v in pairs:
                        idx = _element_index(t)
                        if idx:
                            elements[idx[0]].append((idx[1], idx[2], v, node.lineno))
            # Rodrigues' rotation: one sum with cos(a), sin(a) and 1 - cos(a) of one angle
            if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add | ast.Sub):
                uses = scope.trig_uses(node)
                one_minus_cos = {
                    a
                    for sub in _walk_scope(node)
                    if isinstance(sub, ast.BinOp)
                    and isinstance(sub.op, ast.Sub)
                    and isinstance(sub.left, ast.Constant)
                    and sub.left.value == 1
                    for f, a in scope.trig_uses(sub.right)
                    if f == "cos"
                }
                if one_minus_cos & {a for f, a in uses if f == "sin"}:
                    found.add((fname, "rodrigues", node.lineno))
            # Earth rate: a float literal, or an Earth-rate name times cos/sin
            if isinstance(node, ast.Constant) and isinstance(node.value, float):
                if abs(node.value - 7.292115e-5) <= 1e-3 * 7.292115e-5:
                    found.add((fname, "earth_rate_literal", node.lineno))
            if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult):
                # the factors of the whole product chain (omega_e * rho * cos(lat) too)
                factors = _factors(node)
                rates = [f for f in factors if _EARTH_RATE.match(_name(f))]
                others = [f for f in factors if not _EARTH_RATE.match(_name(f))]
                if rates and any(scope.trig_uses(f) for f in others):
                    found.add((fname, "earth_rate_product", node.lineno))
            # a Schuler-type period 2 pi / sqrt(k)
            if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div):
                has_pi = any(_name(sub) == "pi" for sub in ast.walk(node.left))
                if has_pi and isinstance(node.right, ast.Call) and _name(node.right.func) == "sqrt":
                    found.add((fname, "period_from_sqrt", node.lineno))
            # Coriolis / centripetal / transport-theorem terms: a cross product with Earth rate
            if isinstance(node, ast.Call) and _name(node.func) == "cross":
                if any(_has_earth_rate(a) for a in node.args):
                    found.add((fname, "earth_rate_cross", node.lineno))
        for _array, elts in elements.items():
            line = min(e[3] for e in elts)
            uses = set().union(*(scope.trig_uses(v) for _, _, v, _ in elts))
            if len(elts) >= 2 and _cos_and_sin_of_one_angle(uses):
                found.add((fname, "cos_sin_array", line))
            by_index = {(i, j): v for i, j, v, _ in elts}
            for (i, j), v in by_index.items():
                w = by_index.get((j, i))
                if i < j and w is not None:
                    neg = [
                        isinstance(x, ast.UnaryOp) and isinstance(x.op, ast.USub) for x in (v, w)
                    ]
                    if neg.count(True) == 1:
                        found.add((fname, "skew", line))
    return found


# --------------------------------------------------------------------------------------------
# the heuristic flags re-typed formulas and passes calls of the generated ones
# --------------------------------------------------------------------------------------------
RETYPED = {
    "rotation_display": """
def c3(psi):
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
""",
    "rotation_elements": """
def mat(roll, pitch):
    sr, cr = np.sin(roll), np.cos(roll)
    m = np.empty(roll.shape + (3, 3))
    m[..., 1, 1] = cr
    m[..., 1, 2] = sr * np.cos(pitch)
""",
    "rotation_inline": """
def up(lat, lon):
    return np.stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)], -1)
""",
    "skew_elements": """
def skew(w):
    m = np.zeros((w.shape[0], 3, 3))
    m[:, 0, 1], m[:, 0, 2] = -w[:, 2], w[:, 1]
    m[:, 1, 0], m[:, 1, 2] = w[:, 2], -w[:, 0]
    return m
""",
    "skew_display": """
def skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
""",
    "earth_rate_product": """
def rhs(lat, we):
    cl, sl = np.cos(lat), np.sin(lat)
    return np.column_stack((we * cl, np.zeros(3), -we * sl))
""",
    "earth_rate_inline": """
def w_ie(site):
    return site.omega_ie * np.cos(site.lat)
""",
    "earth_rate_chain": """
def v_east(sc, rho):
    return sc.earth.omega_e * rho * np.cos(sc.route.lat0)
""",
    "earth_rate_literal": """
OMEGA = 7.2921151467e-5
""",
    "coriolis_cross": """
def rhs(w_ie, w_en, v):
    return np.cross(2 * w_ie + w_en, v)
""",
    "centripetal_cross": """
def rhs(w_ie, r):
    return np.cross(w_ie, np.cross(w_ie, r))
""",
    "schuler_period": """
def constants(k_sh):
    return {"schuler_period_s": float(2 * np.pi / np.sqrt(k_sh))}
""",
    "ground_velocity_cross": """
def ground(traj, tr):
    return tr.v_i - np.cross(frames.earth_rate_e(traj.earth.omega_e), tr.r_i)
""",
    "rodrigues": """
def rotate(v, k, angle):
    cos, sin = np.cos(angle), np.sin(angle)
    return v * cos + np.cross(k, v) * sin + k * (k @ v) * (1 - cos)
""",
    "rodrigues_inline": """
def rotate(v, k, a):
    return v * np.cos(a) + np.cross(k, v) * np.sin(a) + k * (k @ v) * (1.0 - np.cos(a))
""",
}

CLEAN = """
def rhs(traj, lat, vn, ve, rho, w):
    w_ie = frames.earth_rate_n(traj.earth.omega_e, lat)
    c_dot = C @ frames.skew(w[:, 0], w[:, 1], w[:, 2])
    s = vc * (tau - math.sin(two_pi * tau) / two_pi)
    h = np.sin((lat2 - lat1) / 2) ** 2 + np.cos(lat1) * np.cos(lat2) * np.sin(dlon / 2) ** 2
    c_si = np.column_stack((a1, np.cross(up, a1), up))
    v_g = gen.ground_velocity(*tr.v_i, *tr.r_i, *frames.earth_rate_e(traj.earth.omega_e))
    return np.stack([np.cos(a), np.cos(b)], -1), [0.0, 0.0, g]
"""


@pytest.mark.parametrize("case", sorted(RETYPED))
def test_heuristic_flags_a_retyped_formula(case):
    assert findings(RETYPED[case]), f"{case} is not flagged"


def test_heuristic_passes_calls_of_generated_functions():
    assert findings(CLEAN) == set()


# --------------------------------------------------------------------------------------------
# the repository
# --------------------------------------------------------------------------------------------
def _references() -> set[tuple[str, str]]:
    """(generated module, function) pairs referenced by code under pipeline/ (not generated)."""
    refs: set[tuple[str, str]] = set()
    for path in sorted((ROOT / "pipeline").rglob("*.py")):
        if path.parent.name == "generated":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        alias: dict[str, str] = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module == "pipeline.generated":
                for a in node.names:
                    alias[a.asname or a.name] = a.name
            elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith(
                "pipeline.generated."
            ):
                refs.update((node.module.rsplit(".", 1)[1], a.name) for a in node.names)
            elif isinstance(node, ast.Import):
                for a in node.names:
                    if a.name.startswith("pipeline.generated.") and a.asname:
                        alias[a.asname] = a.name.rsplit(".", 1)[1]
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Attribute)
                and isinstance(node.value, ast.Name)
                and node.value.id in alias
            ):
                refs.add((alias[node.value.id], node.attr))
    return refs


@pytest.mark.parametrize("path", GENERATED, ids=lambda p: p.stem)
def test_every_generated_function_is_called_or_declared_audit_only(path):
    module = importlib.import_module(f"pipeline.generated.{path.stem}")
    audit_only = getattr(module, "AUDIT_ONLY", {})
    assert set(audit_only) <= set(module.__all__), "AUDIT_ONLY names unknown functions"
    for name, reason in audit_only.items():
        assert reason.strip() and "\n" not in reason, f"{name}: the reason must be one line"
    refs = {f for m, f in _references() if m == path.stem}
    uncalled = [f for f in module.__all__ if f not in refs and f not in audit_only]
    assert not uncalled, (
        f"{path.relative_to(ROOT)}: {uncalled} are generated but never called by pipeline/; "
        "call them, or declare them audit_only='<reason>' in the generator"
    )
    called_anyway = sorted(set(audit_only) & refs)
    assert not called_anyway, f"declared audit-only but called by pipeline/: {called_anyway}"


def test_no_paper_module_builds_its_own_frames_formula():
    found = {}
    for pkg in PAPER_DIRS:
        for path in sorted(pkg.rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            for fname, rule, line in findings(path.read_text(encoding="utf-8")):
                key = (rel, fname, rule)
                if key not in ALLOWED:
                    found.setdefault(key, line)
    assert not found, (
        "modules of paper packages build a rotation matrix, skew matrix or Earth rate by hand "
        "(call pipeline.generated.frames, or declare a false positive in ALLOWED):\n"
        + "\n".join(f"  {p}:{line} in {f}: {r}" for (p, f, r), line in sorted(found.items()))
    )


def test_every_declared_false_positive_is_still_found():
    """A stale ALLOWED entry (the code it excused is gone) is removed, not kept."""
    seen = set()
    for pkg in PAPER_DIRS:
        for path in sorted(pkg.rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            seen.update((rel, f, r) for f, r, _ in findings(path.read_text(encoding="utf-8")))
    assert set(ALLOWED) <= seen, f"stale ALLOWED entries: {sorted(set(ALLOWED) - seen)}"
