"""Bad input through Python: every Scene field out of range raises InputError (a ValueError)
naming the field, the value and the allowed range, before any work; NotConverged is a
RuntimeError; a Rust panic becomes InternalError (an ordinary Exception)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import asperity
from asperity import _native
from conftest import SYSTEM_2

# field, bad value, the error's field, a piece of the allowed range in the message
TABLE = [
    ("system_size_m", -1.0, "system_size_m", "allowed 1e-12 <= system_size_m <= 1000"),
    ("system_size_m", math.nan, "system_size_m", "allowed 1e-12 <= system_size_m <= 1000"),
    ("rolloff_wavelength_m", 1.0, "rolloff_wavelength_m", "allowed 0 < rolloff_wavelength_m <= system_size_m"),
    ("short_wavelength_m", 0.0, "short_wavelength_m", "allowed 1e-12 <= short_wavelength_m <= 1000"),
    ("hurst", 1.5, "hurst", "allowed 0.001 <= hurst <= 1"),
    ("hurst", "abc", "hurst", "allowed 0.001 <= hurst <= 1"),
    ("rms_gradient", -2.0, "rms_gradient", "allowed 1e-6 <= rms_gradient <= 100"),
    ("rms_height_m", -1.0, "rms_height_m", "allowed 1e-15 <= rms_height_m <= 1000"),
    ("contact_modulus_pa", 0.0, "contact_modulus_pa", "allowed 0.001 <= contact_modulus_pa <= 1e15"),
    ("surface_energy_j_m2", -0.1, "surface_energy_j_m2", "allowed 0 <= surface_energy_j_m2 <= 1000"),
    ("surface_energy_j_m2", math.inf, "surface_energy_j_m2", "allowed 0 <= surface_energy_j_m2 <= 1000"),
    ("range_m", 0.0, "range_m", "allowed 1e-15 <= range_m <= 1"),
    ("pressure", -1.0, "pressure", "allowed 1e-12 <= pressure <= 1000"),
    ("pressure", 1e300, "pressure", "invalid pressure = 1e300: allowed 1e-12 <= pressure <= 1000"),
    ("pressure", math.nan, "pressure", "allowed 1e-12 <= pressure <= 1000"),
    ("thickness_qr", 0.0, "thickness_qr", "allowed 1e-6 <= thickness_qr <= 1e12, or inf"),
    ("thickness_qr", "thick", "thickness_qr", "allowed 1e-6 <= thickness_qr <= 1e12, or inf"),
    ("model", 7, "model", "allowed 1, 2, 3, 4, 5, custom, yp08 or xu24"),
    ("model", "five", "model", "allowed 1, 2, 3, 4, 5, custom, yp08 or xu24"),
    ("c1", 2.0, "c1/c2", "W(a) = 1 - c1(1-a^2) - c2(1-a^4) >= 0 for all 0 <= a <= 1"),
    ("c2", 5.0, "c1/c2", "W(a) = 1 - c1(1-a^2) - c2(1-a^4) >= 0 for all 0 <= a <= 1"),
    ("alpha", -1.0, "alpha", "allowed 0 <= alpha <= 4"),
    ("k_griffith", -1.0, "k_griffith", "allowed 0 < k_griffith <= 100"),
    ("cap", "maybe", "cap", "allowed True or False"),
    ("fudge_gamma", 0.5, "model", "allowed yp08 or xu24 when fudge_gamma is given"),
]


@pytest.mark.parametrize("field,value,err_field,allowed", TABLE)
def test_every_field_is_checked_in_the_constructor_and_in_replace(field, value, err_field, allowed):
    custom = {"model": "custom"} if field in ("c1", "c2", "alpha", "k_griffith", "cap") else {}
    base = {k: v for k, v in SYSTEM_2.items() if not (field == "rms_height_m" and k == "rms_gradient")}
    for make in (
        lambda: asperity.Scene(**{**base, **custom, field: value}),
        lambda: asperity.Scene.preset("system-2").replace(**{field: value}),
    ):
        with pytest.raises(asperity.InputError) as e:
            make()
        assert isinstance(e.value, ValueError)
        msg = str(e.value)
        assert allowed in msg, msg
        if err_field is not None:
            assert e.value.field == err_field, (e.value.field, msg)
            assert err_field in msg
            assert e.value.value is not None and e.value.allowed is not None


def test_message_is_one_line_with_value_and_range():
    with pytest.raises(asperity.InputError) as e:
        asperity.Scene.preset("system-2").replace(thickness_qr=-1)
    assert str(e.value) == "invalid thickness_qr = -1: allowed 1e-6 <= thickness_qr <= 1e12, or inf"
    assert (e.value.field, e.value.key, e.value.value) == ("thickness_qr", "load.thickness_qr", "-1")
    assert e.value.allowed == "1e-6 <= thickness_qr <= 1e12, or inf"


def test_unknown_keyword_and_preset():
    with pytest.raises(TypeError):
        asperity.Scene.preset("system-2").replace(pressur=0.1)  # type: ignore[call-arg]
    with pytest.raises(asperity.InputError) as e:
        asperity.Scene.preset("no-such-preset")
    assert e.value.field == "preset"


def test_every_scene_field_is_in_the_table():
    import inspect

    names = [p for p in inspect.signature(asperity.Scene).parameters]
    assert sorted(set(f for f, *_ in TABLE)) == sorted(names)


def test_fudge_gamma_range():
    with pytest.raises(asperity.InputError) as e:
        asperity.Scene.preset("system-1").replace(model="yp08", surface_energy_j_m2=0.0, fudge_gamma=2.0)
    assert e.value.field == "fudge_gamma" and "0 < fudge_gamma <= 1" in str(e.value)


def test_a_model_of_the_literature_refuses_adhesion():
    with pytest.raises(asperity.InputError):
        asperity.Scene.preset("system-2").replace(model="yp08")


def test_function_arguments_are_checked():
    s = asperity.Scene.preset("system-1")
    with pytest.raises(asperity.InputError) as e:
        asperity.evaluate(s, sigma_points=0)
    assert e.value.field == "sigma_points"
    with pytest.raises(asperity.InputError) as e:
        asperity.sweep(s, [0.1, 0.01])
    assert e.value.field == "pressures"
    with pytest.raises(asperity.InputError) as e:
        asperity.sweep(s, [1e-3, 1e9])
    assert e.value.field == "pressure"
    with pytest.raises(asperity.InputError) as e:
        asperity.sweep_thickness(s, [0.0, 1.0])
    assert e.value.field == "thickness_qr"
    with pytest.raises(asperity.InputError) as e:
        asperity.sweep_thickness(s, [1.0, math.inf])
    assert e.value.field == "thickness_qr" and "finite" in str(e.value)
    with pytest.raises(asperity.InputError) as e:
        asperity.gfmd(s, grid=2)
    assert e.value.field == "grid"
    with pytest.raises(asperity.InputError) as e:
        asperity.gfmd(s, np.zeros((8, 8)), 1e-6)
    with pytest.raises(asperity.InputError) as e:
        asperity.psd(np.ones((8, 8)), -1.0)
    assert e.value.field == "size"
    with pytest.raises(asperity.InputError) as e:
        asperity.psd(np.ones((2, 2, 2)), 1.0)
    assert e.value.field == "heights"


def test_not_converged_is_a_runtime_error():
    s = asperity.Scene.preset("system-1").replace(pressure=0.05)
    with pytest.raises(asperity.NotConverged) as e:
        asperity.gfmd(s, grid=32, max_iterations=1)
    assert isinstance(e.value, RuntimeError)
    assert isinstance(e.value, asperity.AsperityError)
    assert e.value.solver and e.value.reason


@pytest.mark.parametrize("where", ["worker", "caller"])
def test_a_panic_becomes_an_exception(where):
    try:
        _native._panic(where)
    except Exception as e:  # an ordinary Exception, not a BaseException
        assert isinstance(e, asperity.InternalError)
        assert isinstance(e, asperity.AsperityError)
        assert "test panic" in str(e)
    else:
        raise AssertionError("no exception")


def test_every_error_is_an_asperity_error():
    with pytest.raises(asperity.AsperityError) as e:
        asperity.Scene.preset("system-1").replace(thickness_qr=-1)
    assert isinstance(e.value, asperity.InputError) and isinstance(e.value, ValueError)
