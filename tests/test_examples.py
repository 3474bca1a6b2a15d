"""Each example runs (quickly, with few samples)."""

import importlib.util
import warnings
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _load(name):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_audit_demo(tmp_path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        doc = _load("audit_demo").main(tmp_path, 32)
    assert doc["schema"] == "critmoment.report/1" and doc["verdict"] in ("SAFE", "CONDITIONAL")
    assert (tmp_path / "report.html").is_file() and (tmp_path / "traj.npz").is_file()


def test_heavy_box_is_conditional(tmp_path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        audit = _load("heavy_box").main(tmp_path, 32)
    assert audit.verdict.value == "CONDITIONAL"


@pytest.mark.slow
def test_validate_demo():
    result = _load("validate_demo").main(8)
    assert result.to_json()["samples"] == 8
