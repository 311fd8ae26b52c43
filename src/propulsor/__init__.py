"""propulsor: CAD and manufacturing-export pipeline for wheel-walking propulsors
and tracked running gear.

Layers (each importable alone):
    laws/, gears/   pure math (numpy/scipy only)
    geometry/       2D closed profiles (numpy/scipy only)
    solids/         cadquery / OCCT solids from profiles
    checks/         B-rep, mesh and motion checks (OCP, trimesh, manifold3d)
    export/         STEP, STL/3MF, DXF, CSV, plots, report, manifest
    parts/          part types: parameters -> library -> outputs
"""

__version__ = "0.1.0"
