"""Print kits: a proven part turned into pieces a desktop FDM printer makes and a rig that runs them.

printers.py   printer profiles and FDM allowances (data in printers/*.toml)
scale.py      the standard scale at which every piece fits the bed; printability limits
layout.py     pieces laid on their largest face, shelf-packed onto plates
slicer.py     PrusaSlicer as the judge of a plate
"""
