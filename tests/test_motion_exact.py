"""Exact numbers of the motion checks (checks/motion/) on small geometry made in each test: issue 36's mutation
tests.  Each expected value is computed here independently (by hand, by a brute-force search, by shapely), never
by the function under test."""

from __future__ import annotations

import math

import numpy as np
import pytest


def test_placeholder_imports():
    import propulsor.checks.motion.transmission  # noqa: F401
