"""numpy's own ``arctan2`` in compiled kernels: ``atan2(y, x)``, the float ``np.arctan2(y, x)`` gives on this machine.

numpy does not compute arctan2 with the C library: on a processor with AVX-512 (x86-64 Linux wheels) its float64 loop
calls Intel's SVML, vendored in numpy and exported from its core module (``__svml_atan28_ha``, eight lanes, each
lane on its own), which differs from the C library's ``atan2`` (what numba's ``math.atan2`` calls) in the last bit on
about 1 % of arguments (2 million random pairs here).  Elsewhere (no AVX-512, or numpy told not to use it through
``NPY_DISABLE_CPU_FEATURES``) numpy calls the C library's ``atan2``.  So a kernel that must give the floats of numpy
code (the proofs' rotation angles: tests hold each kernel to the numpy formulation it replaced) calls this, which
calls what numpy calls: SVML's function on one lane (the others zero), or the C library.

:data:`KIND` says which (``"svml"`` or ``"libm"``); the compiled kernels' disk cache is keyed on it
(:mod:`propulsor.nbcache`), so a kernel compiled for one is never loaded where numpy takes the other.
Compiled into the kernels that call it: a change here compiles them again (``nbcache.INTRINSICS``).
"""

from __future__ import annotations

import ctypes
import math

from llvmlite import ir
from numba import types
from numba.core import cgutils
from numba.extending import intrinsic

__all__ = ["KIND", "atan2"]

#: SVML's float64 arctan2 of eight lanes, as numpy's AVX-512 loop calls it
_SVML_ATAN2 = "__svml_atan28_ha"


#: argument pairs (y, x) whose arctan2 differs in the last bit between SVML's function and the C library's
_PROBES = (("-0x1.29c92d69cd8ecp+0", "-0x1.328945a769678p-2"), ("-0x1.2dc9ef10faf83p-1", "-0x1.57b45fae6facfp-2"),
           ("-0x1.5aeef5dc33d86p+0", "-0x1.4cc98e9e78765p-1"), ("-0x1.1bfe5b871023fp+0", "-0x1.6c0efdb56cf24p-1"),
           ("-0x1.5bb9a5199d0b3p-6", "0x1.22abd4aae8a38p-8"), ("0x1.caa413359eba8p-1", "-0x1.3e114fd6c0b58p+0"))


def _numpy_kind() -> str:
    """``"svml"`` where numpy's float64 arctan2 is not the C library's on the probes and numpy exports SVML's
    ``__svml_atan28_ha`` (then registered with LLVM for the kernels), else ``"libm"``: what numpy does, asked of
    numpy itself (its processor dispatch, ``NPY_DISABLE_CPU_FEATURES`` included), not guessed from the processor."""
    import numpy as np

    y = np.array([float.fromhex(a) for a, _ in _PROBES])
    x = np.array([float.fromhex(b) for _, b in _PROBES])
    if np.arctan2(y, x).tolist() == [math.atan2(a, b) for a, b in zip(y.tolist(), x.tolist())]:
        return "libm"
    try:
        import numpy._core._multiarray_umath as umath

        address = ctypes.cast(getattr(ctypes.CDLL(umath.__file__), _SVML_ATAN2), ctypes.c_void_p).value
    except (ImportError, AttributeError, OSError):  # a numpy of another make: the tests of the kernels will tell
        return "libm"
    import llvmlite.binding as llvm

    llvm.add_symbol(_SVML_ATAN2, address)
    return "svml"


#: what numpy's float64 arctan2 calls here: "svml" or "libm"
KIND = _numpy_kind()


@intrinsic
def atan2(typingctx, y, x):
    """``np.arctan2(y, x)`` of two floats, the same float (SVML's function on one lane, or the C library's)."""
    sig = types.float64(types.float64, types.float64)

    def codegen(context, builder, signature, args):
        if KIND != "svml":
            return context.get_function(math.atan2, signature)(builder, args)
        d = ir.DoubleType()
        v = ir.VectorType(d, 8)
        fn = cgutils.get_or_insert_function(builder.module, ir.FunctionType(v, [v, v]), _SVML_ATAN2)
        lane = ir.Constant(ir.IntType(32), 0)
        zero = ir.Constant(v, None)
        vy = builder.insert_element(zero, args[0], lane)
        vx = builder.insert_element(zero, args[1], lane)
        return builder.extract_element(builder.call(fn, [vy, vx]), lane)

    return sig, codegen
