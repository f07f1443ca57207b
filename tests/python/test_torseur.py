"""The Python package against the command line, sympy and derivations by hand."""

import json
import os
import subprocess
import sys
import threading

import pytest
import sympy

import torseur
from conftest import ROOT, SPECS

SPEC = str(ROOT / "derivations" / "regulateur_centrifuge.json")
PENDULUM = str(ROOT / "examples" / "pendule_simple.json")
t = sympy.Symbol("t")


def is_zero(e) -> bool:
    """Decides e = 0 exactly for a polynomial (or quotient) in the cos and sin of the
    coordinates, their rates and the parameters: sums of angles expanded, then each cos q and
    sin q written with u = tan(q/2) (cos = (1 − u²)/(1 + u²), sin = 2u/(1 + u²)), so that
    sin² + cos² = 1 holds by algebra, and the numerator expanded."""
    e = sympy.expand_trig(sympy.sympify(e))
    subs = {}
    for f in e.atoms(sympy.cos, sympy.sin):
        arg = f.args[0]
        u = sympy.Symbol(f"u_{sympy.srepr(arg)}")
        subs[sympy.cos(arg)] = (1 - u**2) / (1 + u**2)
        subs[sympy.sin(arg)] = 2 * u / (1 + u**2)
    # Derivatives first become symbols, so that substituting into q(t) leaves them whole.
    ders = {d: sympy.Symbol(f"d_{sympy.srepr(d)}") for d in e.atoms(sympy.Derivative)}
    e = e.xreplace(ders).xreplace(subs)
    num, _ = sympy.fraction(sympy.together(e))
    return sympy.expand(num) == 0


def components(v):
    """A derivation's value as a flat list of canonical or presentation texts."""
    if v["kind"] == "torsor":
        return None
    c = v["canonical"]
    p = v["presentation"]
    if isinstance(c, str):
        return [(c, p)]
    if c and isinstance(c[0], list):
        return [(x, y) for rc, rp in zip(c, p) for x, y in zip(rc, rp)]
    return list(zip(c, p))


def flat(canonical):
    if isinstance(canonical, dict):
        return [x for k in ("resultant", "moment") for x in canonical[k]]
    if isinstance(canonical, str):
        return [canonical]
    if canonical and isinstance(canonical[0], list):
        return [x for row in canonical for x in row]
    return list(canonical)


@pytest.mark.parametrize("spec", [s.stem for s in SPECS])
def test_every_quantity_of_every_spec_is_the_clis(spec, cli, loaded):
    """Each quantity of the CLI's `derive --json`, derived from Python: the same canonical
    text under every hypothesis, and (sympy deciding) equal to the CLI's presentation form,
    which a different printer writes."""
    m = loaded[spec]
    coords = m.coordinates
    from torseur._sympy import to_sympy

    for q in cli[spec]["quantities"]:
        d = m.derive(q["id"])
        v = q["value"]
        if v["kind"] == "torsor":
            assert d.canonical == {k: v[k]["canonical"] for k in ("resultant", "moment")}, q["id"]
            pairs = [
                (c, p)
                for k in ("resultant", "moment")
                for c, p in zip(v[k]["canonical"], v[k]["presentation"])
            ]
        else:
            assert d.canonical == v["canonical"], q["id"]
            pairs = components(v)
        for h, hv in q.get("hypotheses", {}).items():
            dh = m.derive(q["id"], hypothesis=h)
            expected = (
                {k: hv[k]["canonical"] for k in ("resultant", "moment")}
                if hv["kind"] == "torsor"
                else hv["canonical"]
            )
            assert dh.canonical == expected, (q["id"], h)
        # The Python value through sympy against the CLI's presentation text through sympy.
        mine = d.to_sympy()
        if isinstance(mine, dict):
            mine = list(mine["resultant"]) + list(mine["moment"])
        elif isinstance(mine, sympy.MatrixBase):
            mine = list(mine)
        else:
            mine = [mine]
        assert len(mine) == len(pairs)
        for x, (_, presentation) in zip(mine, pairs):
            assert is_zero(x - to_sympy(presentation, coords)), (spec, q["id"], presentation)


def test_the_simple_pendulum_is_lagranges_equation_derived_in_sympy():
    """eom(θ) of the README's first spec against Lagrange's equation derived here in sympy:
    T = ½ m l² θ̇², V = −m g l cos θ, d/dt ∂L/∂θ̇ − ∂L/∂θ = m l² θ̈ + m g l sin θ."""
    m = torseur.load(PENDULUM)
    mass, l, g = sympy.symbols("m l g")
    th = sympy.Function("theta")(t)
    lag = sympy.Rational(1, 2) * mass * l**2 * th.diff(t) ** 2 + mass * g * l * sympy.cos(th)
    eq = sympy.diff(lag.diff(th.diff(t)), t) - lag.diff(th)
    assert sympy.expand(m.derive("eom(theta)").to_sympy() - eq) == 0
    # The equation divided by m l is the same equation, up to the factor m l.
    v = m.verify("l*ddot(theta) + g*sin(theta) = 0")
    assert v and v.factor in ("m*l", "l*m"), v.message
    # As a value it is not eom(θ) identically, only along the motions (both are zero there):
    # the difference is (1 − m l)/(m l) × eom(θ).
    v = m.verify("eom(theta)", "l*ddot(theta) + g*sin(theta)")
    assert "along the motions" in v.message and "not identically" in v.message, v.message


def test_to_sympy_follows_the_notation():
    m = torseur.load(SPEC)
    # Ω(2/0) in B1 = θ̇2 x⃗1 + θ̇1 z⃗1 (the rotation θ2 about x⃗1 after θ1 about z⃗0, by hand).
    w = m.derive("Omega(2/0) in B1").to_sympy()
    th1, th2 = sympy.Function("theta1")(t), sympy.Function("theta2")(t)
    assert w == sympy.Matrix([th2.diff(t), 0, th1.diff(t)])
    assert m.derive("Omega(2/0) in B1").basis == "B1"
    a2 = sympy.Symbol("A2")
    e = m.derive("delta(O2,2/0).x2", hypothesis="H1").to_sympy()
    assert e.coeff(th2.diff(t, 2)) == a2 + sympy.Symbol("m2") * sympy.Symbol("L2") ** 2


def test_verify_answers_true_false_and_the_difference():
    m = torseur.load(SPEC)
    ok = m.verify("V(G2,2/0) in B2", "-(L1 + L2*cos(theta2))*dot(theta1)*x1 + L2*dot(theta2)*z2")
    assert ok and ok.difference == ["0", "0", "0"]
    # A sign error on the z2 component (by hand: V·z2 = L2 θ̇2): the difference is −2 L2 θ̇2.
    bad = m.verify("V(G2,2/0) in B2", "-(L1 + L2*cos(theta2))*dot(theta1)*x1 - L2*dot(theta2)*z2")
    assert not bad
    assert is_zero(
        sympy.sympify(0)
        + torseur._sympy.to_sympy(bad.difference[2], m.coordinates)
        + 2 * sympy.Symbol("L2") * sympy.Function("theta2")(t).diff(t)
    )
    assert "NOT" in bad.message or "not" in bad.message


def test_eval_gives_numbers_by_hand():
    m = torseur.load(SPEC)
    # V(G2,2/0) in B2 = [−(L1 + L2 cos θ2) θ̇1, 0, L2 θ̇2] (README, by hand).
    values = {
        "parameters": {"L1": 0.1, "L2": 0.2},
        "coordinates": {"theta1": [0, 2, 0], "theta2": [0.5, 3, 0]},
    }
    got = m.eval(values, ["V(G2,2/0) in B2"])["V(G2,2/0) in B2"]
    import math

    want = [-(0.1 + 0.2 * math.cos(0.5)) * 2, 0, 0.2 * 3]
    assert all(abs(a - b) <= 1e-12 * (1 + abs(b)) for a, b in zip(got, want)), got


def test_check_agrees_with_the_float_backend():
    r = torseur.load(PENDULUM).check(samples=5, seed=3)
    assert r and r.rows and all(row["ok"] for row in r.rows)


def test_errors_are_python_exceptions_naming_the_place():
    with pytest.raises(torseur.TorseurError, match="frames"):
        torseur.load({"title": "x", "frames": [{"name": "1", "parent": "nowhere"}]})
    m = torseur.load(SPEC)
    with pytest.raises(torseur.TorseurError, match="quantity"):
        m.derive("delta(O2,2/0")
    with pytest.raises(torseur.TorseurError, match="H9"):
        m.derive("C_m", hypothesis="H9")
    with pytest.raises(torseur.TorseurError, match="values"):
        m.eval({"parameters": {"nosuch": 1}}, ["C_m"])
    with pytest.raises(torseur.TorseurError, match="scenario"):
        m.simulate("nosuch")
    with pytest.raises(TypeError):
        torseur.load(3)


def test_a_second_process_gets_a_clear_python_error_never_an_abort():
    torseur.load(PENDULUM)  # this process holds the lock from now on
    code = "import torseur\ntry:\n    torseur.load(%r)\nexcept torseur.BusyError as e:\n    print('busy:', e)\n" % PENDULUM
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "busy:" in r.stdout and "one process at a time" in r.stdout, r.stdout


def test_a_second_thread_gets_an_error_never_an_abort():
    m = torseur.load(PENDULUM)
    errors = []

    def other():
        try:
            torseur.load(PENDULUM)
        except torseur.TorseurError as e:
            errors.append(str(e))
        try:
            m.derive("eom(theta)")
        except torseur.TorseurError as e:
            errors.append(str(e))

    th = threading.Thread(target=other)
    th.start()
    th.join()
    assert len(errors) == 2 and all("one thread at a time" in e for e in errors), errors
    assert m.derive("eom(theta)").kind == "scalar"  # the loading thread goes on


def test_the_answer_key_is_the_clis_and_its_pdf_is_written(cli_outputs, tmp_path):
    m = torseur.load(SPEC)
    assert m.answer_key() == cli_outputs["tex"]
    pdf = tmp_path / "corrige.pdf"
    m.answer_key(pdf=pdf)
    assert pdf.read_bytes().startswith(b"%PDF")


def test_the_answer_key_writes_through_a_link_and_refuses_a_directory(tmp_path):
    """As the CLI's outputs: a symbolic link is written through (the link stays a link), and
    a path that names a directory is refused, nothing written."""
    m = torseur.load(PENDULUM)
    real = tmp_path / "real.pdf"
    real.write_text("old")
    link = tmp_path / "k.pdf"
    link.symlink_to(real)
    m.answer_key(pdf=link)
    assert link.is_symlink() and real.read_bytes().startswith(b"%PDF")
    folder = tmp_path / "d.pdf"
    folder.mkdir()
    with pytest.raises(torseur.TorseurError):
        m.answer_key(pdf=folder)
    assert folder.is_dir() and list(folder.iterdir()) == []
    assert sorted(p.name for p in tmp_path.iterdir()) == ["d.pdf", "k.pdf", "real.pdf"]


def test_simulate_gives_the_clis_columns(cli_outputs):
    run = torseur.load(SPEC).simulate("sans_frottement")
    lines = cli_outputs["csv"].strip().splitlines()
    header = lines[0].split(",")
    rows = [[float(x) for x in l.split(",")] for l in lines[1:]]
    assert len(rows) == len(run.times)
    for k, name in enumerate(header):
        col = run.times if k == 0 else run.columns[name.split(" ")[0]]
        assert all(abs(r[k] - c) <= 1e-9 * (1 + abs(c)) for r, c in zip(rows, col)), name


def test_results_show_in_jupyter_in_the_courses_notation():
    m = torseur.load(SPEC)
    d = m.derive("delta(O2,2/0).x2", hypothesis="H1")
    latex = d._repr_latex_()
    assert latex.startswith("$\\begin{aligned}") and latex.endswith("\\end{aligned}$")
    assert "\\delta" in latex and "\\ddot" in latex
    assert "delta(O2,2/0).x2" in repr(d)


def test_the_notebook_runs_and_shows_its_results(cli_outputs):
    code, stderr, executed = cli_outputs["notebook"]
    assert code == 0, stderr
    nb = json.loads(executed.read_text())
    text = json.dumps([c.get("outputs", []) for c in nb["cells"] if c["cell_type"] == "code"])
    # The derived δ(O2,2/0)·x2 shown as LaTeX, the hand result verified, the run-up plotted.
    assert "text/latex" in text and "\\\\delta" in text
    assert "verified: True" in text
    assert "image/png" in text
