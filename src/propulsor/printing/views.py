"""Pictures of a kit's assembled model for the maker: a side view, an exploded view and one picture a
step (the pieces placed so far, those of the step in colour).  Each is the pieces' triangles seen
along a direction, painted far to near and shaded by their slope to the light."""

from __future__ import annotations

import numpy as np

#: (azimuth, elevation) of the views, degrees: side (from −y), three-quarter
SIDE, THREE_QUARTER = (0.0, 0.0), (-35.0, 25.0)


def _basis(view):
    """(right, up, towards the viewer) of a view (azimuth, elevation): at (0, 0) the viewer is at −y."""
    az, el = np.radians(view)
    right = np.array([np.cos(az), np.sin(az), 0.0])
    towards = np.array([np.sin(az) * np.cos(el), -np.cos(az) * np.cos(el), np.sin(el)])
    up = np.cross(towards, right)
    return right, up, towards


def draw(ax, items, view=THREE_QUARTER, dim: set | None = None) -> None:
    """items: [(label, mesh, colour)] placed; `dim`: labels drawn pale grey (placed in earlier steps)."""
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import to_rgb

    right, up, towards = _basis(view)
    polys, depth, colours = [], [], []
    for label, mesh, colour in items:
        tri = np.asarray(mesh.triangles)
        n = np.asarray(mesh.face_normals)
        facing = n @ towards > 1e-6
        tri, n = tri[facing], n[facing]
        if not len(tri):
            continue
        xy = np.stack([tri @ right, tri @ up], axis=-1)
        polys.append(xy)
        depth.append(tri.mean(axis=1) @ towards)
        base = np.array(to_rgb("0.85" if dim and label in dim else colour))
        light = np.clip(0.45 + 0.55 * (n @ (towards + up) / np.sqrt(2.0)), 0.25, 1.0)
        colours.append(np.clip(base[None, :] * light[:, None], 0.0, 1.0))
    if not polys:
        return
    polys, depth, colours = np.concatenate(polys), np.concatenate(depth), np.concatenate(colours)
    order = np.argsort(depth)
    ax.add_collection(PolyCollection(polys[order], facecolors=colours[order], edgecolors="face", linewidths=0.1))
    pts = polys.reshape(-1, 2)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.05 * float(max(hi - lo))
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")
    ax.axis("off")


def exploded(items, gap: float):
    """The items moved apart along z by their level (the height of their lowest point, to 0.1 mm): each
    level `gap` above the one below; pieces on one level move together."""
    levels = sorted({round(float(m.bounds[0][2]), 1) for _, m, _ in items})
    out = []
    for label, mesh, colour in items:
        m = mesh.copy()
        m.apply_translation((0.0, 0.0, levels.index(round(float(mesh.bounds[0][2]), 1)) * gap))
        out.append((label, m, colour))
    return out


def picture(w, name: str, items, title: str, view=THREE_QUARTER, dim=None) -> str:
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 5))
    draw(ax, items, view, dim)
    ax.set_title(title, fontsize=10)
    w.add_plot(name, fig)
    plt.close(fig)
    return f"plots/{name}.png"
