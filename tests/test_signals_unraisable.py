"""After SIGINT / SIGTERM the command line says one line: a multiprocessing finaliser whose construction the signal
cut short (its weakref set, its key not) raises AttributeError when its object dies as the process ends; that is the
signal's doing and not printed (CI, 2026-11-29: 'Exception ignored in: <Finalize object, dead>' after the one line).
Any other error in a finaliser is still printed, and nothing is hidden when no signal came."""
from __future__ import annotations

import gc
import sys
import weakref
from multiprocessing.util import Finalize

import pytest

from propulsor import signals


class _Obj:
    pass


def _half_built_finalizer_dies():
    """A Finalize cut short after its weakref (as a signal inside Finalize.__init__ leaves it); its object dies."""
    obj = _Obj()
    fin = Finalize.__new__(Finalize)
    fin._weakref = weakref.ref(obj, fin)
    fin._callback, fin._args, fin._kwargs = (lambda: None), (), {}
    del obj
    gc.collect()
    return fin


@pytest.fixture
def hook(monkeypatch):
    monkeypatch.setattr(sys, "unraisablehook", signals.unraisable)
    yield
    signals.SIGNALLED.clear()


def test_a_half_built_finalizer_after_a_signal_is_not_printed(hook, capsys):
    signals.SIGNALLED[:] = [15]
    fin = _half_built_finalizer_dies()
    assert not hasattr(fin, "_key")
    assert capsys.readouterr().err == ""


def test_without_a_signal_the_same_error_is_printed(hook, capsys):
    signals.SIGNALLED.clear()
    _half_built_finalizer_dies()
    err = capsys.readouterr().err
    assert "Exception ignored in" in err and "_key" in err


def test_after_a_signal_other_errors_of_finalisers_are_printed(hook, capsys):
    signals.SIGNALLED[:] = [15]

    class Bad:
        def __del__(self):
            raise ValueError("a real fault")

    Bad()
    gc.collect()
    assert "a real fault" in capsys.readouterr().err
