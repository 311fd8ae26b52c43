"""Stand-ins the in-process tests share.

``SaidWriter`` takes the output writer's place (``propulsor.outputs``) in a part's design, proof and sheet steps: it
keeps what the steps said (progress lines, checks, tables, plots, notes, files waited for) so that a test can read
them back, and writes nothing.  ``record_generate_pair`` takes the place of the pair generator in a module that calls
it, recording each call and answering with the next outcome.
"""
from __future__ import annotations

from types import SimpleNamespace


class SaidWriter:
    """The parts of the output writer the steps use, with what they said."""

    draws_plots = True  # a build's writer: the steps draw their figures (``OutputWriter.draws_plots``)

    def __init__(self, folder=None):
        self.derived, self.checks, self.tables, self.plots = {}, [], {}, {}
        self.notes, self.said, self.waited = [], [], []
        self.folder = folder

    def progress(self, message):
        self.said.append(message)

    def add_checks(self, checks):
        self.checks += list(checks)

    def add_table(self, name, columns, rows):
        self.tables[name] = (columns, rows)

    def add_plot(self, name, fig):
        self.plots[name] = fig

    def add_note(self, text):
        self.notes.append(text)

    def wait_for_files(self, *names):
        self.waited.append(names)


def record_generate_pair(monkeypatch, module, outcomes):
    """``module.generate_pair`` replaced: each call recorded (pc, drv, dvn, frame, progress) and answered by the next
    of ``outcomes`` (an exception raised, else returned as the (driver, driven) pair)."""
    calls = []

    def fake(pc, spec_driver, spec_driven, frame, progress=None):
        calls.append(SimpleNamespace(pc=pc, drv=spec_driver, dvn=spec_driven, frame=frame, progress=progress))
        out = outcomes[len(calls) - 1]
        if isinstance(out, BaseException):
            raise out
        return out

    monkeypatch.setattr(module, "generate_pair", fake)
    return calls
