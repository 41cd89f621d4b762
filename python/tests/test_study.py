"""repro.study against repro run: the same rows, the cache kept through Ctrl-C."""

import csv
import json
import os
import subprocess
import sys

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


# Four cases that are their own bases (S = 0.5 %, tau0 = 6 MPa, pipeline/base.rs): each
# solve is one case of the study and one cache entry.
OWN_BASES = FOUR.replace("tau0_mpa = 5.0", "tau0_mpa = 6.0").replace("slip = 0.02", "slip = 0.005")


def rows_of(result):
    """Rows as lists of strings, whether pandas gave a DataFrame or not."""
    if isinstance(result, list):
        return result
    return result.astype(str).to_dict("records")


def csv_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture
def four(tmp_path):
    path = tmp_path / "four.toml"
    path.write_text(FOUR)
    return path


def test_four_cases_give_the_cli_csv(cli, four, tmp_path):
    cli("run", four, "--level", 5, "--out", tmp_path / "cli", "--no-cache", "-q")
    out = tmp_path / "py"
    rows = repro.study(four, level=5, cache=None, out=out)
    assert len(rows) == 4
    assert (out / "four.csv").read_bytes() == (tmp_path / "cli" / "four.csv").read_bytes()


def test_rows_are_a_dataframe_with_pandas(four, tmp_path):
    pd = pytest.importorskip("pandas")
    out = tmp_path / "out"
    rows = repro.study(four, level=5, cache=tmp_path / "cache", out=out)
    assert isinstance(rows, pd.DataFrame)
    expected = csv_rows(out / "four.csv")
    assert list(rows.columns) == list(expected[0])
    assert len(rows) == len(expected) == 4
    # Each cell is the CSV's: its number read back exactly, its text, or NaN where empty.
    for got, want in zip(rows.to_dict("records"), expected):
        for key, text in want.items():
            value = got[key]
            if text == "":
                assert pd.isna(value), key
            else:
                try:
                    number = float(text)
                except ValueError:
                    assert value == text, key
                else:
                    assert float(value) == number, key


def test_rows_are_dicts_of_strings_without_pandas(four, tmp_path, monkeypatch):
    # A None in sys.modules makes `import pandas` raise ImportError, as without pandas.
    monkeypatch.setitem(sys.modules, "pandas", None)
    out = tmp_path / "out"
    rows = repro.study(four, level=5, cache=tmp_path / "cache", out=out)
    assert isinstance(rows, list)
    assert rows == csv_rows(out / "four.csv")


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


# Interrupts a study of OWN_BASES from its progress callback, in a process of its own whose
# rayon pool has one thread (the pool is built once per process): the callback raises
# KeyboardInterrupt, or sends the process SIGINT as Ctrl-C does, at the first case in the
# cache. Prints whether the study raised KeyboardInterrupt and what the callback heard.
INTERRUPT = """
import json, os, signal, sys
import repro

sweep, cache, how = sys.argv[1:]
heard = []
# Python makes SIGINT KeyboardInterrupt only where it was not ignored at start-up, and a
# background job of a shell (`cmd &`, nohup) starts with it ignored: Ctrl-C's handler here.
signal.signal(signal.SIGINT, signal.default_int_handler)

def progress(done, total):
    heard.append(done)
    if how == "raise":
        raise KeyboardInterrupt
    if len(heard) == 1:
        os.kill(os.getpid(), signal.SIGINT)

try:
    repro.study(sweep, level=5, cache=cache, progress=progress)
    raised = False
except KeyboardInterrupt:
    raised = True
print(json.dumps({"raised": raised, "heard": heard}))
"""


@pytest.mark.parametrize("how", ["raise", "sigint"])
def test_interrupt_keeps_the_solved_cases(tmp_path, how):
    sweep = tmp_path / "own.toml"
    sweep.write_text(OWN_BASES)
    cache = tmp_path / "cache"
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    run = subprocess.run([sys.executable, "-c", INTERRUPT, sweep, cache, how], env=env,
                         capture_output=True, text=True, check=True)
    told = json.loads(run.stdout)
    assert told["raised"] and told["heard"] == [1]
    kept = sum(name.endswith(".json") for _, _, names in os.walk(cache) for name in names)
    if how == "raise":
        # The callback raises in the worker before it takes up the next case: one case.
        assert kept == 1
    else:
        # Ctrl-C reaches the study in its calling thread, which sets the stop flag within
        # its 20 ms poll: the worker may have started the next case by then, not all four.
        assert 1 <= kept < 4
    # The rerun takes those from the cache and solves the rest: its reports count on from
    # the cached cases.
    seen = []
    rows = repro.study(sweep, level=5, cache=cache, progress=lambda d, t: seen.append((d, t)))
    assert len(rows) == 4
    assert seen == [(done, 4) for done in range(kept + 1, 5)]


def test_bad_sweep_names_its_file(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[grid]\nph_gpa = 'x'\n")
    with pytest.raises(ValueError, match="bad.toml"):
        repro.study(bad, level=5, cache=None)
