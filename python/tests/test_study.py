"""repro.study against repro run: the same rows, the cache kept through Ctrl-C."""

import csv
import os

import pytest

import repro

FOUR = """title = "Four cases of a gear oil on a 10 mm ball"

[physics]
viscosity = "roelands"
density = "dowson-higginson"
rheology = "eyring"

[defaults]
alpha_per_gpa = 18.0
eta0_mpa_s = 60.0
rx_m = 5.0e-3
d = 1.0
e_prime_gpa = 231.0
tau0_mpa = 5.0
slip = 0.02

[grid]
ph_gpa = [1.0, 2.0]
um_m_s = [1.0, 4.0]
"""


def rows_of(result):
    """Rows as lists of strings, whether pandas gave a DataFrame or not."""
    if isinstance(result, list):
        return result
    return result.astype(str).to_dict("records")


@pytest.fixture
def four(tmp_path):
    path = tmp_path / "four.toml"
    path.write_text(FOUR)
    return path


def test_four_cases_give_the_cli_csv(cli, four, tmp_path):
    cli("run", four, "--level", 5, "--out", tmp_path / "cli", "--no-cache", "-q")
    with open(tmp_path / "cli" / "four.csv", newline="") as f:
        expected = list(csv.DictReader(f))
    out = tmp_path / "py"
    rows = repro.study(four, level=5, cache=None, out=out)
    assert len(rows) == 4
    assert (out / "four.csv").read_bytes() == (tmp_path / "cli" / "four.csv").read_bytes()
    if isinstance(rows, list):
        assert rows == expected


def test_a_dict_is_a_sweep_file(four, tmp_path):
    import tomllib

    with open(four, "rb") as f:
        as_dict = tomllib.load(f)
    seen = []
    rows = repro.study(as_dict, level=5, cache=tmp_path / "cache",
                       progress=lambda done, total: seen.append((done, total)))
    assert len(rows) == 4
    assert seen and seen[-1][0] == seen[-1][1]
    # Again from the cache: the same rows.
    assert rows_of(repro.study(as_dict, level=5, cache=tmp_path / "cache")) == rows_of(rows)


def test_interrupt_keeps_the_solved_cases(four, tmp_path):
    cache = tmp_path / "cache"

    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        repro.study(four, level=5, cache=cache, progress=stop)
    kept = sum(len(files) for _, _, files in os.walk(cache))
    assert kept >= 1
    rows = repro.study(four, level=5, cache=cache)
    assert len(rows) == 4


def test_bad_sweep_names_its_file(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[grid]\nph_gpa = 'x'\n")
    with pytest.raises(ValueError, match="bad.toml"):
        repro.study(bad, level=5, cache=None)
