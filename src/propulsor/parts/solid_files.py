"""The files of one solid and of one assembly, written and checked (the jobs :class:`.writer.OutputWriter` runs in
its forked workers, or in its own process): a solid's STEP with the B-rep checks and the STEP round trip, its STL and
3MF with the mesh checks and its picture; an assembly's GLB and picture from its solids' meshes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..parallel import threads_ok

#: the folder of the isometric pictures of every solid and assembly
VIEWS = "views"


def solid_files_and_checks(folder: str, name: str, solid, expected_genus, volume: float, forked: bool, key=None):
    """STEP, STL and 3MF of one solid in `folder`, its isometric picture ``views/<name>.png``, and every
    shared check on them; returns (list of Check, (vertices, faces) of the mesh, for the assemblies).

    B-rep validity (OCCT), STEP written and re-imported (one solid, same volume), tessellation
    within the chord tolerance, mesh validity (closed, oriented, one body, genus, no
    self-intersection, volume against the B-rep).  The two halves, :func:`solid_step_and_checks` and
    :func:`solid_mesh_and_checks`, are independent: the writer runs them in two workers at once."""
    checks = solid_step_and_checks(folder, name, solid, volume, key)
    mesh_checks, mesh = solid_mesh_and_checks(folder, name, solid, expected_genus, volume, forked, key)
    return checks + mesh_checks, mesh


def solid_step_and_checks(folder: str, name: str, solid, volume: float | None = None, key=None) -> list:
    """The B-rep checks of one solid, its STEP file and the STEP round trip; returns the checks.  ``volume``: the
    solid's B-rep volume (mm^3) when the caller has it (the writer's, of the same B-rep: a forked worker's copy is
    OCCT's binary form of it, the same surfaces to the bit); else computed here.  ``key``: the solid's in its
    batch (:func:`.solid_cache.solid_key`): the file and checks of the same solid from another build of the batch
    are taken where it has made them, and this one's kept for the others."""
    from . import solid_cache

    files = (f"{name}.step",)
    kept = solid_cache.fetch(key, "step", folder, files)
    if kept is not None:
        return kept
    checks = _step_and_checks(Path(folder), name, solid, volume)
    solid_cache.store(key, "step", folder, files, checks)
    return checks


def _step_and_checks(folder: Path, name: str, solid, volume: float | None) -> list:
    from ..checks.brep import brep_checks, step_roundtrip_check
    from ..export.step import write_step
    from ..solids.kernel import volume as kernel_volume

    # the exact-vs-triangulated volume cross-check is made on the exported mesh itself
    v = kernel_volume(solid) if volume is None else float(volume)  # the B-rep check and the STEP round trip
    checks = list(brep_checks(solid, name, cross_check_volume=False, volume_mm3=v))
    step = folder / f"{name}.step"
    write_step(solid, step, name)
    checks.append(step_roundtrip_check(solid, step, name, built_volume=v))
    return checks


def solid_mesh_and_checks(folder: str, name: str, solid, expected_genus, volume: float, forked: bool, key=None):
    """STL and 3MF of one solid, the mesh checks and ``views/<name>.png``; returns (list of Check,
    (vertices, faces) of the mesh).  ``key``: as :func:`solid_step_and_checks` takes it (a mesh made in threads
    kept apart from one made in one)."""
    from . import solid_cache

    # OCCT's mesher threads only in a build allowed more than one process and not in a forked worker
    parallel = bool(not forked and threads_ok())
    files = (f"{name}.stl", f"{name}.3mf", f"{VIEWS}/{name}.png")
    half = f"mesh-{int(parallel)}"
    kept = solid_cache.fetch(key, half, folder, files)
    if kept is not None:
        return kept
    got = _mesh_and_checks(Path(folder), name, solid, expected_genus, volume, parallel)
    solid_cache.store(key, half, folder, files, got)
    return got


def _mesh_and_checks(folder: Path, name: str, solid, expected_genus, volume: float, parallel: bool):
    from ..checks.mesh import mesh_checks
    from ..export.mesh import tessellate, write_3mf, write_stl
    from ..export.render import palette_colour, render_iso

    mesh = tessellate(solid, parallel=parallel)
    write_stl(mesh, folder / f"{name}.stl")
    write_3mf(mesh, folder / f"{name}.3mf", name)
    checks = mesh_checks(mesh, name, expected_genus=expected_genus, brep_volume=volume)
    vertices, faces = np.asarray(mesh.vertices, np.float64), np.asarray(mesh.faces, np.int64)
    render_iso([(vertices, faces, None, palette_colour(0))], folder / VIEWS / f"{name}.png")
    return checks, (vertices, faces)


def _import_solid_work() -> None:
    """The modules :func:`solid_files_and_checks` runs (mesh, checks, STEP, pictures), imported before the
    workers are forked: each worker then starts with them instead of importing them again."""
    from ..checks import brep, mesh  # noqa: F401
    from ..checks.tri_tri import pairs_intersect
    from ..export import mesh as _mesh, render, step  # noqa: F401
    from ..solids import kernel  # noqa: F401

    none = np.zeros(0, np.int64)  # the compiled narrow phase loaded from numba's cache, no pair to test
    pairs_intersect(np.zeros((3, 3)), np.zeros((1, 3), np.int64), none, none, np.zeros((1, 3)), np.zeros(1), 1e-9)


def mesh_of(solid, forked: bool):
    """(vertices, faces) of a solid that is in an assembly but has no files of its own."""
    from ..export.mesh import tessellate

    mesh = tessellate(solid, parallel=not forked and threads_ok())
    return np.asarray(mesh.vertices, np.float64), np.asarray(mesh.faces, np.int64)


def assembly_model(folder: str, name: str, meshes: dict, components, from_below: bool = False,
                   motions=()) -> None:
    """``<name>.glb`` and ``views/<name>.png`` of an assembly from its solids' meshes;
    components: (component name, solid key, 4×4 placement mm); from_below: the picture seen from below;
    motions: the GLB's animations (:func:`export.glb.write_glb`).  The two halves,
    :func:`assembly_glb` and :func:`assembly_picture`, are independent (the writer runs them side by side)."""
    assembly_glb(folder, name, meshes, components, motions)
    assembly_picture(folder, name, meshes, components, from_below)


def assembly_glb(folder: str, name: str, meshes: dict, components, motions=()) -> None:
    """``<name>.glb`` of an assembly (:func:`assembly_model`): the pages that show it carry its bytes as data."""
    from ..export.glb import write_glb

    write_glb(Path(folder) / f"{name}.glb", name, meshes, components, motions)


def assembly_picture(folder: str, name: str, meshes: dict, components, from_below: bool = False) -> None:
    """``views/<name>.png`` of an assembly (:func:`assembly_model`)."""
    from ..export.render import VIEW_DIR, VIEW_DIR_BELOW, palette_colour, render_iso

    items = [(*meshes[key], matrix, palette_colour(k)) for k, (_, key, matrix) in enumerate(components)]
    render_iso(items, Path(folder) / VIEWS / f"{name}.png", view=VIEW_DIR_BELOW if from_below else VIEW_DIR)
