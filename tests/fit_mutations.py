"""Each fit check of a kit made to fail on the kit's own printed pieces.

:func:`recording` records, while a kit is built (``propulsor print``), every fit that
``printing/fits.py`` measures with the very meshes it measured (each piece in its own frame).
:func:`mutations` then changes the printed geometry as a printing or drawing mistake would — the pin
grown or its hole shrunk by the running clearance (a bore drawn without it), the press-fit pin shrunk
or its hole grown to no interference (a hole drawn at the pin's size), the pin grown past what a
printed wall takes — and measures again: the check must fail each time.  A pin's wall to its disc's rim
(:class:`~propulsor.printing.fits.Rim`) fails with a pin moved outward (a wrong centre distance), a pin
grown, or the disc shrunk, each by just more than the wall measured beyond the least feature.
"""

from __future__ import annotations

import contextlib

import numpy as np

from propulsor.printing.fits import PRESS_MAX_MM, Rim, measure, rim_walls


@contextlib.contextmanager
def recording(into: dict):
    """Record {fit name: (Fit, {piece: mesh}, printer, Check)} of every fit measured inside."""
    import propulsor.printing.fits as fits

    real = fits.measure

    def spy(fit, meshes, printer):
        check = real(fit, meshes, printer)
        into[fit.name] = (fit, {n: meshes[n] for n in fit.pieces}, printer, check)
        return check

    with _patched(fits, "measure", spy):
        yield into


@contextlib.contextmanager
def _patched(module, name, value):
    old = getattr(module, name)
    setattr(module, name, value)
    try:
        yield
    finally:
        setattr(module, name, old)


def _grown(mesh, at, delta: float, which=None):
    """The piece with every vertex (or those selected by the mask `which`) moved radially by `delta` (mm)
    from the axis through `at`: a pin or a hole on that axis grows by delta in radius (shrinks when
    delta < 0)."""
    out = mesh.copy()
    v = np.array(out.vertices)
    d = v[:, :2] - np.asarray(at, float)
    r = np.hypot(d[:, 0], d[:, 1])
    scale = np.where(r > 1e-9, (r + delta) / np.maximum(r, 1e-9), 1.0)
    if which is not None:
        scale = np.where(which, scale, 1.0)
    v[:, :2] = np.asarray(at, float) + d * scale[:, None]
    out.vertices = v
    return out


def _rim_parts(mesh, rim: Rim, k: int):
    """(mask of pin k's vertices above the disc, its axis, mask of the disc's vertices) of a Rim's piece."""
    v = np.asarray(mesh.vertices)
    above = (v[:, 2] > rim.pin_z[0] + 1e-3) & (v[:, 2] <= rim.pin_z[1] + 1e-9)
    drawn = np.asarray(rim.pins_at, float)
    nearest = np.argmin(np.hypot(v[:, None, 0] - drawn[None, :, 0], v[:, None, 1] - drawn[None, :, 1]), axis=1)
    disc = (v[:, 2] >= rim.disc_z[0] - 1e-9) & (v[:, 2] <= rim.disc_z[1] + 1e-9)
    return above & (nearest == k), rim_walls(mesh, rim)[k][1], disc


def rim_cases(rim: Rim, mesh, delta: float, k: int = 0) -> list[tuple[str, object]]:
    """[(mutation, the mutated piece)]: pin k moved outward, pin k grown, the disc shrunk, each by delta."""
    pin, axis, disc = _rim_parts(mesh, rim, k)
    out_dir = (axis - np.asarray(rim.at, float)) / np.hypot(*(axis - np.asarray(rim.at, float)))
    moved = mesh.copy()
    v = np.array(moved.vertices)
    v[pin, :2] += delta * out_dir
    moved.vertices = v
    return [(f"pin {k + 1} moved outward by {delta:.3f} mm (a wrong centre distance)", moved),
            (f"pin {k + 1} grown by {delta:.3f} mm", _grown(mesh, axis, delta, pin)),
            (f"disc shrunk by {delta:.3f} mm", _grown(mesh, rim.at, -delta, disc))]


def mutations(record) -> list[tuple[str, bool, str]]:
    """[(mutation, the check passed under it, its message)] of one recorded fit: the pin changed, then
    the hole (a check blind to either piece passes one of them)."""
    fit, meshes, printer, _ = record
    if isinstance(fit, Rim):
        # at each pin in turn, just past the wall the check allows there
        out = []
        for k, (wall, *_) in enumerate(rim_walls(meshes[fit.piece], fit)):
            for what, mutated in rim_cases(fit, meshes[fit.piece], wall - printer.min_feature_mm + 0.02, k):
                c = measure(fit, {fit.piece: mutated}, printer)
                out.append((what, c.passed, c.message))
        return out
    if fit.kind == "running":
        # the bore drawn without the running clearance: the pin fills the hole but for a trace
        delta = printer.running_clearance_mm + 0.02
        cases = [(f"pin grown by {delta:g} mm (no running clearance)", fit.pin, fit.pin_at, delta),
                 (f"hole shrunk by {delta:g} mm (no running clearance)", fit.hole, fit.hole_at, -delta)]
    else:
        delta = printer.press_fit_mm + 0.02
        cases = [(f"pin shrunk by {delta:g} mm (no interference)", fit.pin, fit.pin_at, -delta),
                 (f"hole grown by {delta:g} mm (no interference)", fit.hole, fit.hole_at, delta),
                 (f"pin grown past the {PRESS_MAX_MM:g} mm a printed wall takes", fit.pin, fit.pin_at,
                  PRESS_MAX_MM + 0.02)]
    out = []
    for what, piece, at, d in cases:
        mutated = dict(meshes)
        mutated[piece] = _grown(meshes[piece], at, d)
        c = measure(fit, mutated, printer)
        out.append((what, c.passed, c.message))
    return out


def assert_fails_under_mutation(recorded: dict, name: str) -> None:
    """The kit's fit `name` passes as built and fails under each of its mutations."""
    assert name in recorded, f"the kit measured no fit {name} (it measured {sorted(recorded)})"
    check = recorded[name][3]
    assert check.passed, check.message
    for what, passed, message in mutations(recorded[name]):
        assert not passed, f"fit.{name} still passes with the {what}: {message}"
