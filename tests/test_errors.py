"""errors.input_names: lower layers name quantities, a part maps them to its part-file keys."""

import pytest

from propulsor.errors import InputError, input_names


def test_input_names_renames_a_mapped_quantity_and_keeps_the_rest_of_the_message():
    with pytest.raises(InputError) as exc:
        with input_names({"z_H": "driven_teeth", "m": "module_mm"}):
            raise InputError("z_H", 81, "must be a multiple of n = 4", "nearest valid: 80, 84")
    e = exc.value
    assert (e.parameter, e.value, e.limit, e.hint) == ("driven_teeth", 81, "must be a multiple of n = 4",
                                                       "nearest valid: 80, 84")
    assert str(e) == "driven_teeth = 81: must be a multiple of n = 4 (nearest valid: 80, 84)"


def test_input_names_passes_other_errors_unchanged():
    original = InputError("rho_f_star", 0.9, "tool tip rounds overlap (no tip land)")
    with pytest.raises(InputError) as exc:
        with input_names({"m": "module_mm"}):
            raise original
    assert exc.value is original
    with pytest.raises(ZeroDivisionError):
        with input_names({"m": "module_mm"}):
            1 / 0
