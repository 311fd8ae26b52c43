"""cadquery without VTK at import time.

cadquery's modules import VTK names (``vtkmodules.*``, ``OCP.IVtkOCC``, ``OCP.IVtkVTK``) at their top for
its viewers and VTK exports, none of which a build uses; loading VTK costs 0.65 s of CPU, a third of
cadquery's import.  :func:`import_cadquery` imports cadquery with every such name bound to a
:class:`Later`, which loads the real VTK module the first time the name is called or read (so cadquery's
VTK functions still work, later).  Where VTK or cadquery is loaded already, it is a plain import.  Every module of
propulsor that needs cadquery takes it from here (a plain ``import cadquery`` anywhere in a build loads VTK: a build of
one part file reached cadquery first through the extrusion of its solids, 0.79 s of imports).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import types

__all__ = ["import_cadquery", "Later"]

_PREFIXES = ("vtkmodules", "OCP.IVtk")


def _deferred(fullname: str) -> bool:
    return any(fullname == p or fullname.startswith(p + ".") or (p.endswith("IVtk") and fullname.startswith(p))
               for p in _PREFIXES)


class Later:
    """A name of a VTK module, loaded the first time it is called or one of its attributes is read."""

    def __init__(self, module: str, name: str):
        self._where = (module, name)

    def _real(self):
        module, name = self._where
        return getattr(importlib.import_module(module), name)

    def __call__(self, *args, **kwargs):
        return self._real()(*args, **kwargs)

    def __getattr__(self, attr):
        if attr.startswith("__"):  # what typing and copy probe (a type hint of cadquery's) does not load VTK
            raise AttributeError(attr)
        return getattr(self._real(), attr)

    def __repr__(self) -> str:
        return f"<{self._where[0]}.{self._where[1]}, loaded on first use>"


class _Stub(types.ModuleType):
    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return Later(self.__name__, name)


class _StubFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    def find_spec(self, fullname, path=None, target=None):
        if not _deferred(fullname):
            return None
        return importlib.machinery.ModuleSpec(fullname, self, is_package=True)

    def create_module(self, spec):
        module = _Stub(spec.name)
        module.__path__ = []
        return module

    def exec_module(self, module):
        pass


def import_cadquery():
    """``import cadquery`` without loading VTK (see the module); returns the module."""
    if "cadquery" in sys.modules or any(_deferred(m) for m in sys.modules):
        return importlib.import_module("cadquery")
    finder = _StubFinder()
    sys.meta_path.insert(0, finder)
    try:
        return importlib.import_module("cadquery")
    finally:
        sys.meta_path.remove(finder)
        for name in [m for m in sys.modules if _deferred(m)]:
            if isinstance(sys.modules[name], _Stub):
                del sys.modules[name]
