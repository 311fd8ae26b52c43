"""The processor's fused multiply-add in compiled kernels: ``fma(a, b, c)`` = a b + c rounded once.

numba lowers ``a * b + c`` to two roundings (no contraction).  Where a kernel must give the floats of a numpy
expression that BLAS computes with fused multiply-adds (a matrix product, OpenBLAS's gemv and gemm), it writes the
same fused operations with this (LLVM's ``llvm.fma.f64``: the processor's instruction, or its exact emulation).
Compiled into the kernels that call it: a change here compiles them again (``nbcache.SOURCES``).
"""

from __future__ import annotations

from llvmlite import ir
from numba import types
from numba.extending import intrinsic

__all__ = ["fma"]


@intrinsic
def fma(typingctx, a, b, c):
    """a b + c rounded once (LLVM's ``llvm.fma.f64``: the processor's fused multiply-add, or its exact emulation)."""
    sig = types.float64(types.float64, types.float64, types.float64)

    def codegen(context, builder, signature, args):
        d = ir.DoubleType()
        return builder.call(builder.module.declare_intrinsic("llvm.fma", [d], ir.FunctionType(d, [d, d, d])), args)

    return sig, codegen
