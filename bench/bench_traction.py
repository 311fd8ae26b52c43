"""Benchmark: the final drive's traction step (seed 004 ch. 5.1.2-5.1.3): the characteristic (4 gears x 8
engine points) and its plot, as the build runs it (matplotlib already imported by the build's other plots).

Run: .venv/bin/python bench/bench_traction.py [runs]
Budget (issue 15): < 0.5 s per build for the step.  Prints the median of the computation and of the whole step.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time

TARGET_S = 0.5


class _Writer:
    """The few writer calls the step makes; the plot is saved as the build saves it."""

    def __init__(self, folder: str):
        self.folder, self.derived = folder, {}

    def progress(self, msg):
        pass

    def add_table(self, *a):
        pass

    def add_checks(self, checks):
        pass

    def add_note(self, text):
        pass

    def add_plot(self, name, fig):
        from propulsor.export.plots import save_plot

        save_plot(f"{self.folder}/{name}.png", fig)


def main(runs: int = 5) -> int:
    import matplotlib.pyplot  # noqa: F401  (the build has imported it before this step's plot)

    from propulsor.laws import traction as tr
    from propulsor.parts.final_drive import FinalDriveParams, design
    from propulsor.parts.final_drive.traction import traction
    from propulsor.parts.pipeline import design_of

    dd = design_of(FinalDriveParams(), design)
    calc, step = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(runs):
            t0 = time.perf_counter()
            tr.traction_characteristic(tr.VEHICLE_004, 800.0, 7.852, 4, 0.932)
            calc.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            traction(dd, _Writer(tmp), {})
            step.append(time.perf_counter() - t0)
    med = statistics.median(step)
    print(f"traction characteristic: calculation median {statistics.median(calc) * 1e3:.3f} ms; whole step with the "
          f"plot median {med:.3f} s over {runs} runs ({', '.join(f'{t:.3f}' for t in step)} s); target < {TARGET_S} s")
    return 0 if med < TARGET_S else 1


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 5))
