"""``make mutation``'s runner (mutation/run.py): reading the results of a target never run is refused in one line
naming the target and the missing folder, exit 2 (before, a FileNotFoundError's traceback from inside the reader)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _runner(monkeypatch):
    spec = importlib.util.spec_from_file_location("mutation_run", ROOT / "mutation" / "run.py")
    mod = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, "mutation_run", mod)  # its dataclasses look their module up
    spec.loader.exec_module(mod)
    return mod


def test_report_only_without_results_is_refused_in_one_line(tmp_path, monkeypatch, capsys):
    run = _runner(monkeypatch)
    monkeypatch.setattr(run, "SCRATCH", tmp_path / ".mutation")
    module = "src/propulsor/parts/noncircular_pair/pair_proof.py"
    assert run.main(["--report-only", "--module", module]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert "noncircular_proof" in err[0] and str(tmp_path / ".mutation") in err[0] and "run it first" in err[0]
