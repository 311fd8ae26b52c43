"""ISO 6336 rating (gears/iso6336*.py, gear_materials.py, planetary*.py) checked against the standard's equations
computed here, independently of the code: both sides of every limit and clamp, refusals' messages in full
(issue 36, mutation testing: `make mutation MODULE=gears_rating`).  Fast, in-process, no part builds."""

from __future__ import annotations

import math

import pytest

from propulsor.errors import InputError
from propulsor.gears import iso6336 as iso
