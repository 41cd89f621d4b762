"""The command-line binary the Python results are compared with (REPRO_BIN, or the release
build of the repository's target folder)."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    target = os.environ.get("CARGO_TARGET_DIR", str(ROOT / "target"))
    binary = os.environ.get("REPRO_BIN", os.path.join(target, "release", "repro"))
    if not os.path.exists(binary):
        pytest.fail(f"no repro binary at {binary}: run `cargo build --release` or set REPRO_BIN")

    def run(*args, check=True):
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True,
                              check=check, cwd=ROOT)

    return run
