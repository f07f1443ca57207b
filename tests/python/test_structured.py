"""The structured form printed by `torseur derive --form structured --json`, read back by sympy
(a reader that shares nothing with the printer): every name substituted, each quantity must be
the canonical value `torseur derive --json` prints, and each equation of motion must be
Σ M q'' + h − Q. Equality is exact: cos q and sin q are replaced by the rational
parametrisation ((1 − t²)/(1 + t²), 2t/(1 + t²)), and the difference must cancel to 0."""

import re

import pytest
import sympy as sp

IDENT = re.compile(r"\b(ddot|dot)\((\w+)\)|\b([A-Za-z_]\w*)\b")


def reader():
    symbols = {}

    def sym(name):
        return symbols.setdefault(name, sp.Symbol(name))

    def read(text):
        def swap(m):
            if m.group(1):
                return f"{m.group(1)}_{m.group(2)}"
            return m.group(3)

        text = IDENT.sub(swap, text).replace("^", "**")
        names = {n: sym(n) for n in re.findall(r"\b[A-Za-z_]\w*\b", text) if n not in ("cos", "sin")}
        return sp.parse_expr(text, local_dict={**names, "cos": sp.cos, "sin": sp.sin})

    return read


def rational(e):
    """cos q, sin q by the rational parametrisation of the circle, so that the identity
    cos² + sin² = 1, by which the canonical form is reduced, holds as an identity of fractions."""
    subs = {}
    for f in e.atoms(sp.cos, sp.sin):
        t = sp.Symbol(f"t_{f.args[0]}")
        subs[f] = (1 - t**2) / (1 + t**2) if f.func is sp.cos else 2 * t / (1 + t**2)
    return e.xreplace(subs)


def equal(a, b):
    return sp.cancel(rational(sp.expand(a - b))) == 0


@pytest.mark.parametrize("rel", ["chain/planar_3", "chain/chain_3", "regulateur_centrifuge", "double_pendule"])
def test_the_structured_form_reads_back_to_the_canonical_values(rel, cli_outputs):
    named, canonical = cli_outputs["structured"][rel]
    read = reader()
    values = {}
    for d in named["names"]:
        values[sp.Symbol(d["name"])] = read(d["value"]).xreplace(values)
    by_id = {q["id"]: q["value"] for q in canonical["quantities"]}
    assert [q["id"] for q in named["quantities"]] == list(by_id)
    held = 0
    for q in named["quantities"]:
        if not q["named"]:
            # The engine's own value, as the canonical JSON prints it.
            if by_id[q["id"]]["kind"] == "scalar":
                assert q["value"] == by_id[q["id"]]["canonical"], f"{rel}: {q['id']}"
            continue
        got = read(q["value"]).xreplace(values)
        assert equal(got, read(by_id[q["id"]]["canonical"])), f"{rel}: {q['id']}"
        held += 1
    assert held > 0, rel
    eq = named.get("equations_of_motion")
    if rel == "chain/chain_3":
        assert eq is None  # no theorem of the PFD: dynamic moments only
        return
    assert eq is not None, rel
    coords = eq["coordinates"]
    for i, c in enumerate(coords):
        row = sum(
            read(eq["mass"][i][j]).xreplace(values) * sp.Symbol(f"ddot_{qj}") for j, qj in enumerate(coords)
        )
        row += read(eq["velocity_terms"][i]).xreplace(values) - read(eq["forces"][i]).xreplace(values)
        assert equal(row, read(by_id[f"eom({c})"]["canonical"])), f"{rel}: eom({c})"
