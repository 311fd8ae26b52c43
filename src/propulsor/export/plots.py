"""Plots with matplotlib (Agg backend), written deterministically.

PNG: the 'Software' text chunk is dropped, so the same figure gives the same
bytes.  SVG: no date, a fixed hash salt for element ids.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg", force=False)
import matplotlib.pyplot as plt  # noqa: E402

from ..write_root import prepare  # noqa: E402

_SVG_SALT = "propulsor"


def new_figure(width_in: float = 7.0, height_in: float = 4.5):
    """A figure and one axes (grid on)."""
    fig, ax = plt.subplots(figsize=(width_in, height_in), dpi=100)
    ax.grid(True, lw=0.4, alpha=0.6)
    return fig, ax


def save_plot(path: str | Path, fig, dpi: int = 120) -> Path:
    """Save PNG or SVG (by suffix) without volatile metadata, then close the figure."""
    path = Path(path)
    prepare(path)
    suffix = path.suffix.lower()
    _layout_done(fig)
    try:
        if suffix == ".png":
            fig.savefig(path, format="png", dpi=dpi, metadata={"Software": None}, bbox_inches=None)
        elif suffix == ".svg":
            with matplotlib.rc_context({"svg.hashsalt": _SVG_SALT}):
                fig.savefig(path, format="svg", metadata={"Date": None, "Creator": None})
        elif suffix == ".pdf":
            fig.savefig(path, format="pdf", metadata={"CreationDate": None, "ModDate": None, "Producer": None, "Creator": None})
        else:
            raise ValueError(f"{path}: plot format must be .png, .svg or .pdf")
    finally:
        plt.close(fig)
    return path


def _layout_done(fig) -> None:
    """Drop the placeholder layout engine ``fig.tight_layout()`` leaves behind: it lays nothing out, but a figure
    with any engine is drawn once more (rendering off) before ``savefig`` draws it; without the engine the same
    pixels come from that one draw.  An engine that lays out at every draw (constrained, tight) is kept."""
    from matplotlib.layout_engine import PlaceHolderLayoutEngine

    if isinstance(fig.get_layout_engine(), PlaceHolderLayoutEngine):
        fig.set_layout_engine(None)


#: the font sizes the builds' figures name (legends, notes), beside matplotlib's defaults (10 and 12)
WARM_FONT_SIZES = (6, 7, 8, 9)


def warm() -> None:
    """Draw one throwaway figure as :func:`save_plot` draws one (into memory): the first figure of a process pays
    for pyplot's backend module and the font search (``font_manager.findfont``: each family, style and size scored
    against every installed font once, then cached); a process that draws afterwards, or forks children that draw,
    finds both done.  The same pixels and bytes either way (the caches hold what a figure would compute)."""
    import io

    fig, ax = new_figure()
    ax.plot([0.0, 1.0], [0.0, 1.0], label="a")
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
    ax.set_title("warm")
    for size in WARM_FONT_SIZES:
        ax.text(0.5, 0.5, "a", fontsize=size)
    ax.legend(fontsize=WARM_FONT_SIZES[1])
    fig.tight_layout()
    _layout_done(fig)
    try:
        fig.savefig(io.BytesIO(), format="png", dpi=120, metadata={"Software": None}, bbox_inches=None)
    finally:
        plt.close(fig)


def line_plot(path: str | Path, series, xlabel: str, ylabel: str, title: str = "", markers: bool = False, equal_axes: bool = False) -> Path:
    """Several series on one axes: series = [(x, y, label), ...]; labels carry units."""
    fig, ax = new_figure()
    for s in series:
        x, y, label = s[0], s[1], s[2]
        ax.plot(x, y, marker="." if markers else None, ms=3, lw=1.2, label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)
    if equal_axes:
        ax.set_aspect("equal", adjustable="datalim")
    if any(s[2] for s in series):
        ax.legend(fontsize=8)
    fig.tight_layout()
    return save_plot(path, fig)


def outline_plot(path: str | Path, loops, title: str = "", labels=None) -> Path:
    """Closed outlines (list of (n, 2) arrays) drawn closed, equal axes, mm."""
    import numpy as np

    fig, ax = new_figure(6.0, 6.0)
    for k, p in enumerate(loops):
        p = np.asarray(p, float)
        q = np.vstack([p, p[:1]])
        ax.plot(q[:, 0], q[:, 1], lw=0.8, label=(labels[k] if labels else None))
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
    if title:
        ax.set_title(title)
    if labels:
        ax.legend(fontsize=8)
    fig.tight_layout()
    return save_plot(path, fig)
