"""tests/pixels.py against numpy's row-wise unique: the same colours, counted and ordered alike."""

from __future__ import annotations

import numpy as np
import pytest

from pixels import colour_count, colour_keys, colour_rows


@pytest.mark.parametrize("seed", range(5))
def test_the_colours_are_numpys_unique_rows(seed):
    rng = np.random.default_rng(seed)
    # a picture of few colours (a view on its background) and one of many, with the channels' extremes
    palette = rng.integers(0, 256, (rng.integers(1, 40), 3))
    few = palette[rng.integers(0, len(palette), (60, 80))]
    many = rng.integers(0, 256, (60, 80, 3))
    many[0, 0], many[0, 1], many[0, 2] = (0, 0, 0), (255, 255, 255), (0, 255, 0)
    for img in (few, many, few.astype(np.uint8)):
        rows, inverse = np.unique(img.reshape(-1, 3), axis=0, return_inverse=True)
        keys, kinv = np.unique(colour_keys(img), return_inverse=True)
        assert colour_count(img) == len(rows)
        assert np.array_equal(colour_rows(keys), rows)  # the same colours in the same order
        assert np.array_equal(kinv.ravel(), inverse.ravel())


def test_a_channel_beyond_8_bits_is_refused():
    with pytest.raises(ValueError, match="8-bit"):
        colour_keys(np.array([[0, 256, 0]]))
    with pytest.raises(ValueError, match="8-bit"):
        colour_keys(np.array([[-1, 0, 0]]))
