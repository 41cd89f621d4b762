"""repro.predict and repro.lubricant against repro predict --json."""

import json
import time

import numpy as np
import pytest

import repro

OIL = dict(iso_vg=100, vi=95, rho15=880, base_oil="mineral")
CONTACT = dict(ph=1e9, slip=0.02, tau0=5e6)


def test_predict_is_the_cli_predictor(cli):
    out = json.loads(cli("predict", "--iso-vg", 100, "--vi", 95, "--rho15", 880, "--base-oil",
                         "mineral", "--temperature", 60, "--ph", 1e9, "--um", 5, "--slip",
                         0.02, "--tau0", 5e6, "--json").stdout)
    p = repro.predict(um=5.0, temperature=60.0, refined=True, **CONTACT, **OIL)
    for key in ["tau_c", "mu_bar", "mu", "mu_bar_refined", "mu_refined", "m", "l", "hc_m"]:
        assert p[key].item() == out[key], key
    assert [p["mu_bar_low"].item(), p["mu_bar_high"].item()] == out["mu_bar_band"]
    # Without the refined formula the same Eq. (14).
    fast = repro.predict(um=5.0, temperature=60.0, **CONTACT, **OIL)
    assert fast["mu_bar"].item() == out["mu_bar"] and "mu_bar_refined" not in fast
    lub = repro.lubricant(temperature=60.0, **OIL)
    assert lub["eta0_pa_s"].item() == out["lubricant"]["eta0_pa_s"]
    assert lub["alpha_per_pa"].item() == out["lubricant"]["alpha_per_pa"]
    band = [lub["alpha_low_per_pa"].item(), lub["alpha_high_per_pa"].item()]
    assert band == out["lubricant"]["alpha_band_per_pa"]


def test_predict_of_a_table1_lubricant_and_a_load_is_the_cli_predictor(cli):
    out = json.loads(cli("predict", "--lubricant", "mineral-oil-a", "--temperature", 40,
                         "--load", 500, "--um", 12, "--slip", 0.005, "--tau0", 4e6,
                         "--json").stdout)
    p = repro.predict(lubricant="mineral-oil-a", temperature=40.0, load=500.0, um=12.0,
                      slip=0.005, tau0=4e6, refined=True)
    for key in ["ph_pa", "tau_c", "mu_bar", "mu", "mu_bar_refined", "mu_refined"]:
        assert p[key].item() == out[key], key
    assert out["mu_bar_band"] is None and np.isnan(p["mu_bar_low"].item())


def test_predict_over_ten_thousand_speeds():
    speeds = np.geomspace(0.1, 30.0, 10_000)
    start = time.perf_counter()
    p = repro.predict(um=speeds, temperature=60.0, **CONTACT, **OIL)
    seconds = time.perf_counter() - start
    print(f"predict over 10 000 speeds: {seconds * 1e3:.1f} ms")
    assert p["mu_bar"].shape == (10_000,)
    # Element by element the same as one call per speed.
    for k in [0, 4321, 9999]:
        one = repro.predict(um=speeds[k], temperature=60.0, **CONTACT, **OIL)
        assert one["mu_bar"].item() == p["mu_bar"][k]
    # A faster contact builds a thicker film at the same slip: tau_c = eta S u_m / h_c
    # grows with u_m^(1 - 0.67) or so, so mu-bar grows with speed.
    assert np.all(np.diff(p["tau_c"]) > 0)


def test_predict_broadcasts_arrays():
    p = repro.predict(um=np.array([[1.0], [2.0]]), slip=np.array([0.01, 0.02, 0.03]),
                      ph=1e9, tau0=5e6, temperature=60.0, **OIL)
    assert p["mu_bar"].shape == (2, 3)


def test_table1_lubricant_and_errors():
    lub = repro.lubricant(lubricant="mineral-oil-a", temperature=np.array([40.0, 60.0, 100.0]))
    assert lub["eta0_pa_s"].shape == (3,)
    assert np.all(np.diff(lub["eta0_pa_s"]) < 0)
    assert np.all(np.isnan(lub["alpha_low_per_pa"]))
    with pytest.raises(ValueError, match="^temperature: "):
        repro.lubricant(lubricant="mineral-oil-a", temperature=500.0)
    with pytest.raises(ValueError, match="^rho15"):
        repro.predict(um=1.0, temperature=60.0, iso_vg=100, vi=95, base_oil="mineral",
                      **CONTACT)


# The lubricant and geometry keywords are read by one piece of code for solve, predict and
# lubricant (python/src/args.rs): each refuses what none of its groups takes, as Python does.
@pytest.mark.parametrize("call", [
    repro.solve,
    repro.lubricant,
    lambda **k: repro.predict(um=1.0, temperature=60.0, **CONTACT, **OIL, **k),
], ids=["solve", "lubricant", "predict"])
def test_unknown_or_mistyped_keyword_raises_type_error(call):
    with pytest.raises(TypeError, match="unexpected keyword argument 'nu_40'"):
        call(nu_40=100.0)
    with pytest.raises(TypeError, match="^argument 'expansion15': "):
        call(expansion15="heavy")


def test_geometry_keywords_reach_the_predictor():
    base = repro.predict(um=1.0, temperature=60.0, **CONTACT, **OIL)
    # The default Rx is the command line's (1.03875e-2 m): given, the same bits.
    same = repro.predict(um=1.0, temperature=60.0, rx=1.03875e-2, **CONTACT, **OIL)
    assert same["m"].item() == base["m"].item()
    # A larger ball at the same p_H carries more load in a larger contact: another M.
    other = repro.predict(um=1.0, temperature=60.0, rx=2e-2, ry=3e-2, **CONTACT, **OIL)
    assert other["m"].item() != base["m"].item()
