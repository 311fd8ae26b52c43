"""numba's on-disk cache of the checks' kernels, keyed on every kernel source, not only the kernel's own file.

numba keeps a kernel's compiled code beside its module and reuses it while that one file is unchanged (its mtime and
size).  A kernel that calls a kernel of another module (the as-built contact's ``_track_nb`` calls
``contact_kernels``, which calls ``backlash``) has the callee compiled into it: when only the callee's file changes (a
``git pull`` in a checkout, an edit), numba loads the caller's old code, which runs the old callee, silently.
:func:`bind` keys every cached kernel of a module on the stamps of all the kernel sources (:data:`SOURCES`, the
files of ``checks.kernels.MODULES``): a change to any of them compiles them all again, once; and on which arctan2
numpy calls here (:mod:`propulsor.npmath`, whose kernels call the same).
"""

from __future__ import annotations

import os
from pathlib import Path

_HERE = Path(__file__).resolve().parent
#: sources compiled into the kernels that call them, with no cached kernel of their own (fused.py's fma, npmath.py's
#: arctan2)
INTRINSICS = (str(_HERE / "fused.py"), str(_HERE / "npmath.py"))
#: every source file with cached kernels (``checks.kernels.MODULES``; a test keeps the two lists equal)
SOURCES = tuple(str(_HERE / f) for f in ("checks/tri_tri.py", "checks/motion/nearest.py", "checks/motion/crossing.py",
                                         "checks/motion/backlash.py", "checks/motion/transmission_kernel.py",
                                         "checks/motion/contact_kernels.py",
                                         "checks/motion/contact_reuse.py", "checks/motion/contact_track.py",
                                         "checks/box_pairs.py", "export/normals.py", "export/render.py",
                                         "geometry/spline_foot.py", "laws/fourier_kernels.py",
                                         "laws/cam_kernels.py", "checks/motion/poses.py",
                                         "checks/motion/sweep_steps.py", "laws/walking_kernels.py",
                                         "checks/motion/mesh_load.py", "gears/tooth_load_kernels.py")) + INTRINSICS

__all__ = ["SOURCES", "INTRINSICS", "bind", "stamp"]


def stamp(files=SOURCES) -> tuple:
    """(mtime, size) of each file, in order: what numba compares for one file, here for all of them."""
    out = []
    for f in files:
        st = os.stat(f)
        out.append((st.st_mtime, st.st_size))
    return tuple(out)


def bind(namespace: dict, files=SOURCES) -> int:
    """Key the disk cache of each cached kernel in ``namespace`` (a module's ``globals()``, before any kernel of it
    ran) on :func:`stamp` of ``files``; the number of kernels bound.  Where numba's cache is not of the layout read
    here (another numba, caching off) nothing is changed: the kernels cache as numba does by itself."""
    from numba.core.registry import CPUDispatcher

    s = None
    n = 0
    for value in list(namespace.values()):
        if not isinstance(value, CPUDispatcher):
            continue
        cache_file = getattr(getattr(value, "_cache", None), "_cache_file", None)
        if cache_file is None or not hasattr(cache_file, "_source_stamp"):
            continue
        if s is None:
            from .npmath import KIND  # registers SVML's arctan2 with LLVM before any cached kernel is loaded

            # and which arctan2 numpy takes here (npmath): a kernel compiled for the other is not loaded
            s = stamp(files) + (("numpy arctan2", KIND),)
        cache_file._source_stamp = s
        n += 1
    return n
