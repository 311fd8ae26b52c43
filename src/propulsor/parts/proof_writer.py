"""ProofWriter: an :class:`~propulsor.parts.writer.OutputWriter` that keeps what the steps compute —
derived values, their descriptions, checks, notes, tables (as rows) — and writes no file.

The design and proof steps of a part (:meth:`propulsor.parts.pipeline.Pipeline.prove`) and the design
depth of a study run into it: the same step code as a build, so the same numbers, without solids, their
file checks, pictures or a temporary folder.  A step that asks for a solid, an assembly or a file path is
not a proof step: that is an error of the part type's declaration (RuntimeError naming it).
"""

from __future__ import annotations

from pathlib import Path

from .writer import OutputWriter

__all__ = ["ProofWriter", "SolidWriter"]


class ProofWriter(OutputWriter):
    """Values only: ``derived``, ``described``, ``checks``, ``notes``, ``tables`` and ``table_rows``
    (name -> (columns, rows) as the step gave them); plots are dropped (the figure closed; ``draws_plots`` False: the
    steps that only draw a figure skip it), DXF outlines kept in ``built_profiles``."""

    draws_plots = False

    def __init__(self, part: str, params, progress=None, source: Path | None = None):
        super().__init__(Path("."), part, params, progress=progress, source=source)
        self.folder = None  # nothing is written: a step that needs the folder is no proof step
        self.table_rows: dict[str, tuple] = {}

    def _no_file(self, what: str):
        raise RuntimeError(f"{self.part}: a proof step asked for {what}; proof steps make values and checks only")

    def path(self, rel: str):
        self._no_file(f"the file {rel}")

    def add_solid(self, name: str, solid, expected_genus=None):
        self._no_file(f"the solid {name}")

    def add_assembly(self, name: str, components, picture_from_below: bool = False):
        self._no_file(f"the assembly {name}")

    def add_known_mesh(self, solid, vertices, faces) -> None:
        pass  # a mesh for an assembly's picture: none is drawn here

    def add_dxf(self, name: str, cut_profiles, ref_curves=(), beside: bool = False):
        self.built_profiles[name] = list(cut_profiles)

    def add_table(self, name: str, columns, rows):
        self.tables.append(f"tables/{name}.csv")
        self.table_rows[name] = (columns, rows)  # as given (export.tables.write_csv's forms: also a dict of columns)

    def add_plot(self, name: str, fig):
        import matplotlib.pyplot as plt

        plt.close(fig)

    def finish(self) -> list[str]:
        """The unexpected check failures (nothing to write)."""
        self.close()
        return self.failures()


class SolidWriter(ProofWriter):
    """What a part's solid steps make (:meth:`propulsor.parts.pipeline.Pipeline.solids`): the solids
    (``built_solids``, and each one's ``<name>_volume_mm3``), the assemblies (``built_assemblies``) and the DXF
    outlines (``built_profiles``), in memory; no file is written and none of the files' checks runs."""

    def add_solid(self, name: str, solid, expected_genus=None):
        self.built_solids[name] = solid
        self.derived[f"{name}_volume_mm3"] = float(solid.Volume())

    def add_assembly(self, name: str, components, picture_from_below: bool = False):
        self.built_assemblies[name] = list(components)
