"""torseur from Python: exact rigid-body dynamics in the course's torsor notation.

>>> import torseur
>>> m = torseur.load("derivations/regulateur_centrifuge.json")
>>> d = m.derive("delta(O2,2/0).x2", hypothesis="H1")
>>> bool(m.verify("Omega(2/0) in B1", "[dot(theta2), 0, dot(theta1)]"))
True

A result shows in Jupyter in the course's notation (``_repr_latex_``), converts to sympy
(``to_sympy()``: each parameter a ``Symbol``, each coordinate ``Function(name)(t)``) and keeps
its canonical and presentation texts. Errors are ``torseur.TorseurError`` (a spec, a quantity, an
expression or values refused; the message names the JSON path or the argument) and its subclass
``torseur.BusyError``.

Without a licence key symbolica allows one process per user on the machine (and one thread in
it): the first ``load`` takes the user's torseur lock and keeps it until the interpreter exits;
while another process holds it, ``load`` raises ``BusyError`` at once instead of letting
symbolica abort the interpreter. Symbolica's licence notice is printed on stderr.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import tempfile
import threading
from typing import Any, Dict, List, Optional, Sequence, Union

from . import _torseur
from ._sympy import to_sympy as _to_sympy
from ._torseur import BusyError, TorseurError

__all__ = [
    "load",
    "Mechanism",
    "Result",
    "Verdict",
    "CheckReport",
    "Simulation",
    "TorseurError",
    "BusyError",
]


def load(spec: Union[str, os.PathLike, Dict[str, Any]]) -> "Mechanism":
    """Loads a spec: a file path, a dict (the spec's JSON as Python objects) or JSON text."""
    if isinstance(spec, dict):
        return Mechanism(_torseur.load_text(json.dumps(spec)))
    if isinstance(spec, os.PathLike):
        return Mechanism(_torseur.load_path(os.fspath(spec)))
    if isinstance(spec, str):
        if spec.lstrip().startswith("{"):
            return Mechanism(_torseur.load_text(spec))
        return Mechanism(_torseur.load_path(spec))
    raise TypeError(
        f"torseur.load takes a path, a dict or JSON text, not {type(spec).__name__}"
    )


class Mechanism:
    """A mechanism loaded from a spec; every method runs the engine exactly as the CLI does."""

    def __init__(self, loaded: "_torseur.Loaded"):
        self.__m = loaded
        self._thread = threading.get_ident()
        s = json.loads(self._m.summary())
        self.title: str = s["title"]
        self.parameters: List[str] = s["parameters"]
        self.coordinates: List[str] = s["coordinates"]
        self.hypotheses: List[str] = s["hypotheses"]
        self.quantities: List[str] = s["quantities"]
        self.scenarios: List[str] = s["scenarios"]

    @property
    def _m(self) -> "_torseur.Loaded":
        """The engine's object, from the thread that loaded it only (symbolica's rule)."""
        if threading.get_ident() != self._thread:
            raise TorseurError(
                "this mechanism was loaded by another thread: unlicensed symbolica allows one "
                "thread at a time (use torseur from the thread that loaded it)"
            )
        return self.__m

    def __repr__(self) -> str:
        return f"<torseur.Mechanism {self.title!r}: coordinates {', '.join(self.coordinates)}>"

    def derive(self, quantity: str, hypothesis: Optional[str] = None) -> "Result":
        """The quantity in the course's notation (``"delta(O2,2/0).x2"``, ``"{D(E/0)}_O2 in B1"``,
        ``"eom(theta2)"``, ``"C_m"``), exactly; under a hypothesis of the spec when named."""
        return Result(self, json.loads(self._m.derive(quantity, hypothesis)))

    def verify(
        self, quantity: str, expr: Optional[str] = None, hypothesis: Optional[str] = None
    ) -> "Verdict":
        """Is a hand-written value equal to the derived one? ``verify("C_m", "...")``; or an
        equation alone, ``verify("A2*ddot(theta2) + ... = 0")``. The verdict is true when
        equivalent, and carries the factor and the difference."""
        if expr is None:
            return Verdict(json.loads(self._m.verify(None, quantity, hypothesis)))
        return Verdict(json.loads(self._m.verify(quantity, expr, hypothesis)))

    def eval(
        self,
        values: Union[Dict[str, Any], str],
        quantities: Optional[Sequence[str]] = None,
    ) -> Dict[str, Any]:
        """Numbers at ``values`` (``{"parameters": {...}, "coordinates": {"q": [q, q', q'']}}``,
        the CLI's ``--at`` file): ``{quantity: float | list}`` for the given quantities, or the
        spec's."""
        text = values if isinstance(values, str) else json.dumps(values)
        if isinstance(quantities, str):
            quantities = [quantities]
        out = json.loads(self._m.eval(text, list(quantities or [])))
        result = {}
        for q in out["quantities"]:
            if q["kind"] == "torsor":
                result[q["id"]] = {"resultant": q["resultant"], "moment": q["moment"]}
            else:
                result[q["id"]] = q["value"]
        return result

    def check(self, samples: int = 20, seed: int = 1) -> "CheckReport":
        """Every quantity of the spec against the independent float backend (and its
        dimension); the report is true when all agree within 1e-9 relative."""
        return CheckReport(json.loads(self._m.check(samples, seed)))

    def answer_key(
        self, pdf: Optional[Union[str, os.PathLike]] = None, vectors: str = "sum"
    ) -> str:
        """The answer key (« corrigé ») as LaTeX text. With ``pdf="key.pdf"`` it is also
        compiled by pdflatex (no shell escape) and written there, with its figures beside it
        when it has any (``key-*.png``); an existing file that is not a regular file is never
        replaced."""
        if vectors not in ("sum", "column"):
            raise ValueError('vectors is "sum" or "column"')
        if pdf is None:
            tex, figures = self._m.answer_key("", vectors == "column")
            return tex
        pdf = os.fspath(pdf)
        if not pdf.endswith(".pdf"):
            raise ValueError(f"pdf: `{pdf}` must name a .pdf file")
        stem = os.path.basename(pdf)[: -len(".pdf")]
        prefix = "".join(c if c.isalnum() or c in "-_" else "-" for c in stem) + "-"
        tex, figures = self._m.answer_key(prefix, vectors == "column")
        pdf_bytes = _pdflatex(tex, figures)
        folder = os.path.dirname(os.path.abspath(pdf))
        files = [(os.path.join(folder, name), bytes(data)) for name, data in figures]
        _torseur.write_files(files + [(os.path.abspath(pdf), pdf_bytes)])
        return tex

    def equations_of_motion(self) -> "EquationsOfMotion":
        """The equations of motion as M(q) q̈ + h(q, q̇, t) = Q(q, t): the mass matrix, the
        terms that vanish at rest (Coriolis, centrifugal, viscous), the generalised forces."""
        return EquationsOfMotion(self, json.loads(self._m.equations_of_motion()))

    def simulate(self, scenario: str) -> "Simulation":
        """Integrates a scenario of the spec; columns as numpy arrays when numpy is installed."""
        return Simulation(json.loads(self._m.simulate(scenario)))


def _pdflatex(tex: str, figures) -> bytes:
    if shutil.which("pdflatex") is None:
        raise TorseurError("pdflatex is not installed (run scripts/setup, or install texlive)")
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "key.tex"), "w", encoding="utf-8") as f:
            f.write(tex)
        for name, data in figures:
            with open(os.path.join(d, name), "wb") as f:
                f.write(bytes(data))
        env = dict(os.environ, FORCE_SOURCE_DATE="1")
        env.setdefault("SOURCE_DATE_EPOCH", "0")
        r = subprocess.run(
            ["pdflatex", "-no-shell-escape", "-interaction=nonstopmode", "-halt-on-error", "key.tex"],
            cwd=d,
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        )
        if r.returncode != 0:
            log = r.stdout.decode("utf-8", "replace").splitlines()
            tail = [l for l in log if l.startswith("!") or l.startswith("l.")]
            raise TorseurError("pdflatex rejected the answer key: " + " | ".join(tail))
        with open(os.path.join(d, "key.pdf"), "rb") as f:
            return f.read()


def _latex_block(lines: str) -> str:
    """The engine's ``align*`` lines for a value (its left side included), as one display."""
    return "$\\begin{aligned}" + lines + "\\end{aligned}$"


class Result:
    """A derived quantity: ``kind`` (scalar, vector, matrix, torsor), its texts, its LaTeX,
    the steps of the course's method, and the values under each hypothesis of the spec."""

    def __init__(self, mechanism: Mechanism, j: Dict[str, Any]):
        self._mechanism = mechanism
        self._j = j
        v = j["value"]
        self.quantity: str = j["id"]
        self.hypothesis: Optional[str] = j.get("hypothesis")
        self.kind: str = v["kind"]
        self.basis: Optional[str] = v.get("basis")
        self.point: Optional[str] = v.get("point")
        if self.kind == "torsor":
            self.canonical = {k: v[k]["canonical"] for k in ("resultant", "moment")}
            self.text = {k: v[k]["presentation"] for k in ("resultant", "moment")}
        else:
            self.canonical = v["canonical"]
            self.text = v["presentation"]
        self.latex: str = j["latex"]["value"]
        self.steps: List[Dict[str, Any]] = j.get("steps", [])
        self.hypotheses: Dict[str, Any] = j.get("hypotheses", {})

    def __repr__(self) -> str:
        where = f" under {self.hypothesis}" if self.hypothesis else ""
        return f"<torseur.Result {self.quantity}{where}: {self.text}>"

    def __str__(self) -> str:
        return f"{self.quantity} = {self.text}"

    def _repr_latex_(self) -> str:
        return _latex_block(self.latex)

    def to_sympy(self):
        """The value as sympy: an expression, a Matrix of components on ``basis`` (3×1 for a
        vector, 3×3 for an inertia matrix), or ``{"resultant": ..., "moment": ...}``."""
        import sympy

        names = _Names(self._mechanism)
        if self.kind == "scalar":
            return _to_sympy(self.canonical, names.coordinates)
        if self.kind == "vector":
            return sympy.Matrix([_to_sympy(c, names.coordinates) for c in self.canonical])
        if self.kind == "matrix":
            return sympy.Matrix([[_to_sympy(c, names.coordinates) for c in row] for row in self.canonical])
        return {
            k: sympy.Matrix([_to_sympy(c, names.coordinates) for c in self.canonical[k]])
            for k in ("resultant", "moment")
        }


class EquationsOfMotion:
    """M(q) q̈ + h(q, q̇, t) = Q(q, t), each entry exact: ``coordinates``, and ``mass``,
    ``velocity_terms``, ``forces`` as the engine's presentation texts; ``to_sympy()`` gives
    ``(M, h, Q)`` as sympy matrices."""

    def __init__(self, mechanism: Mechanism, j: Dict[str, Any]):
        self._mechanism = mechanism
        self._j = j
        self.coordinates: List[str] = j["coordinates"]
        self.mass = [[e["presentation"] for e in row] for row in j["mass"]]
        self.velocity_terms = [e["presentation"] for e in j["velocity_terms"]]
        self.forces = [e["presentation"] for e in j["forces"]]

    def __repr__(self) -> str:
        return f"<torseur.EquationsOfMotion of {', '.join(self.coordinates)}>"

    def to_sympy(self):
        import sympy

        names = _Names(self._mechanism).coordinates
        read = lambda e: _to_sympy(e["canonical"], names)
        mass = sympy.Matrix([[read(e) for e in row] for row in self._j["mass"]])
        h = sympy.Matrix([read(e) for e in self._j["velocity_terms"]])
        q = sympy.Matrix([read(e) for e in self._j["forces"]])
        return mass, h, q


class _Names:
    def __init__(self, m: Mechanism):
        self.coordinates = set(m.coordinates)


class Verdict:
    """The answer of ``verify``: true when the hand-written value (or equation) is the
    engine's; ``factor`` (an equation of motion written up to a factor), ``difference``
    (given − derived, per component), ``message`` (the CLI's text)."""

    def __init__(self, j: Dict[str, Any]):
        self._j = j
        self.equivalent: bool = j["equivalent"]
        self.message: str = j["message"]
        self.factor: Optional[str] = j["factor"]
        self.difference: List[str] = [d["canonical"] for d in j["difference"]]
        self.hypothesis: Optional[str] = j["hypothesis"]

    def __bool__(self) -> bool:
        return self.equivalent

    def __repr__(self) -> str:
        return f"<torseur.Verdict {'equivalent' if self.equivalent else 'NOT equivalent'}: {self.message}>"

    def __str__(self) -> str:
        return self.message

    def _repr_latex_(self) -> Optional[str]:
        nonzero = [d["latex"] for d in self._j["difference"] if d["canonical"] != "0"]
        if not nonzero:
            return None
        return "$\\text{difference: } " + ",\\quad ".join(nonzero) + "$"


class CheckReport:
    """The float backend's report: true when every quantity agrees within ``tolerance``."""

    def __init__(self, j: Dict[str, Any]):
        self._j = j
        self.passed: bool = j["passed"]
        self.tolerance: float = j["tolerance"]
        self.rows: List[Dict[str, Any]] = j["quantities"]
        self.dimensions: List[Dict[str, Any]] = j["dimensions"]

    def __bool__(self) -> bool:
        return self.passed

    def __repr__(self) -> str:
        worst = max((r["worst_relative_error"] for r in self.rows), default=0.0)
        return (
            f"<torseur.CheckReport {'passed' if self.passed else 'FAILED'}: "
            f"{len(self.rows)} quantities, worst relative error {worst:.1e}>"
        )


class Simulation:
    """A simulated scenario: ``times`` and ``columns`` (id → values), ``units`` (id → SI unit)."""

    def __init__(self, j: Dict[str, Any]):
        try:
            import numpy

            array = numpy.asarray
        except ImportError:  # pragma: no cover - numpy is optional
            array = list
        self.scenario: str = j["scenario"]
        self.label: str = j["label"]
        self.times = array(j["times"])
        self.columns = {c["id"]: array(c["values"]) for c in j["columns"]}
        self.units = {c["id"]: c["unit"] for c in j["columns"]}
        self.drift: Optional[float] = j["drift"]

    def __getitem__(self, column: str):
        return self.columns[column]

    def __repr__(self) -> str:
        return (
            f"<torseur.Simulation {self.scenario!r}: {len(self.times)} instants, "
            f"columns {', '.join(self.columns)}>"
        )
