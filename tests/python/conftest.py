"""Shared set-up of the Python tests (`pytest tests/python`, after `pip install .`).

symbolica allows one process per user: once this process has loaded a spec it holds the
torseur lock until it exits, so everything that needs another process (the command line's
results, the notebook's kernel) runs here, at the start of the session, before any load.
"""

import json
import os
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SPECS = sorted((ROOT / "derivations").glob("*.json"))
NOTEBOOK = ROOT / "examples" / "regulateur.ipynb"
# Specs whose structured form is read back by sympy (tests/python/test_structured.py).
STRUCTURED = ["chain/planar_3", "chain/chain_3", "regulateur_centrifuge", "double_pendule"]


def torseur_bin() -> pathlib.Path:
    return pathlib.Path(os.environ.get("TORSEUR_BIN", ROOT / "target" / "release" / "torseur"))


def run_cli(args, cwd=None):
    return subprocess.run(
        [str(torseur_bin()), *args], cwd=cwd or ROOT, capture_output=True, text=True, timeout=600
    )


def pytest_sessionstart(session):
    out = pathlib.Path(session.config._tmp_path_factory.mktemp("cli"))
    cli = {}
    for spec in SPECS:
        target = out / f"{spec.stem}.json"
        r = run_cli(["derive", str(spec), "--json", str(target)])
        assert r.returncode == 0, f"torseur derive {spec.name}: {r.stderr}"
        cli[spec.stem] = json.loads(target.read_text())
    # The structured form (--form structured) of a few specs, beside their canonical JSON.
    structured = {}
    for rel in STRUCTURED:
        spec = ROOT / "derivations" / f"{rel}.json"
        named, canonical = out / f"{spec.stem}.structured.json", out / f"{spec.stem}.canonical.json"
        r = run_cli(["derive", str(spec), "--form", "structured", "--json", str(named)])
        assert r.returncode == 0, f"torseur derive {rel} --form structured: {r.stderr}"
        r = run_cli(["derive", str(spec), "--json", str(canonical)])
        assert r.returncode == 0, r.stderr
        structured[rel] = (json.loads(named.read_text()), json.loads(canonical.read_text()))
    # On stdout (no -o): the figures keep their bare names, as from Python without a PDF.
    r = run_cli(["answer-key", "derivations/regulateur_centrifuge.json"])
    assert r.returncode == 0, r.stderr
    tex = r.stdout
    csv = out / "sans_frottement.csv"
    r = run_cli(
        ["simulate", "derivations/regulateur_centrifuge.json", "--scenario", "sans_frottement", "-o", str(csv)]
    )
    assert r.returncode == 0, r.stderr
    # The notebook, executed by its own kernel (a second process) before this one loads.
    executed = out / "regulateur.ipynb"
    r = subprocess.run(
        [sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute", str(NOTEBOOK),
         "--output", str(executed), "--ExecutePreprocessor.timeout=600"],
        cwd=ROOT, capture_output=True, text=True, timeout=900,
    )
    session.config._torseur = {
        "cli": cli,
        "structured": structured,
        "tex": tex,
        "csv": csv.read_text(),
        "notebook": (r.returncode, r.stderr, executed),
    }


@pytest.fixture(scope="session")
def cli(pytestconfig):
    """`torseur derive SPEC --json` of every spec of derivations/, by spec name."""
    return pytestconfig._torseur["cli"]


@pytest.fixture(scope="session")
def cli_outputs(pytestconfig):
    return pytestconfig._torseur


@pytest.fixture(scope="session")
def loaded():
    """Every spec of derivations/, loaded once."""
    import torseur

    return {spec.stem: torseur.load(str(spec)) for spec in SPECS}
