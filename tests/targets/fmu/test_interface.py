"""Validating a user's FMU against the ego interface: every mismatch is listed, clearly."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.targets.fmu import FmuInterfaceError, validate_fmu
from sovarc.targets.fmu.interface import VARIABLES, interface_table

from tests.conftest import Golden
from tests.targets.fmu.fake_fmu import write_fmu

HERE = Path(__file__).parent
INTERFACE_MD = HERE.parents[2] / "targets" / "fmu" / "INTERFACE.md"


def _errors(path: Path) -> str:
    with pytest.raises(FmuInterfaceError) as caught:
        validate_fmu(path)
    return str(caught.value)


def test_a_complete_description_validates_with_every_reference(tmp_path: Path) -> None:
    ego = validate_fmu(write_fmu(tmp_path / "ok.fmu"))
    assert set(ego.refs) == {v.name for v in VARIABLES}
    assert ego.model_identifier == "Fake"


def test_optional_parameters_may_be_missing(tmp_path: Path) -> None:
    ego = validate_fmu(write_fmu(tmp_path / "lean.fmu", drop=("ego_length", "ego_wheelbase")))
    assert "ego_length" not in ego.refs and "accel" in ego.refs


def test_missing_variables_are_all_listed_in_one_error(tmp_path: Path) -> None:
    text = _errors(write_fmu(tmp_path / "partial.fmu", drop=("accel", "obj_3_speed", "path_y_12")))
    assert "missing 3 variable(s) of the ego interface" in text
    assert "path_y_12 (input, Real, m)" in text
    assert "obj_3_speed (input, Real, m/s)" in text
    assert "accel (output, Real, m/s2)" in text
    assert text.startswith(str(tmp_path / "partial.fmu"))  # the file is named, as every sovarc error does


def test_wrong_causality_type_and_unit_each_get_a_line(tmp_path: Path, golden: Golden) -> None:
    path = write_fmu(
        tmp_path / "wrong.fmu",
        drop=("steer",),
        change={
            "accel": {"causality": "input"},
            "obj_count": {"kind": "Real"},
            "ego_speed": {"unit": "km/h"},
            "ego_heading": {"unit": "deg"},  # the same unit: fine
        },
    )
    golden.check(HERE / "fixtures" / "interface_errors.err", _errors(path).replace(str(tmp_path), "TMP") + "\n")


def test_other_fmi_versions_and_broken_files_are_refused(tmp_path: Path) -> None:
    assert "FMI 3.0 FMU: the ego harness runs FMI 2.0" in _errors(write_fmu(tmp_path / "v3.fmu", fmi_version="3.0"))
    assert "FMU not found" in _errors(tmp_path / "nowhere.fmu")
    (tmp_path / "junk.fmu").write_bytes(b"not a zip")
    assert "not an FMU: a zip archive with a modelDescription.xml" in _errors(tmp_path / "junk.fmu")


def test_interface_md_carries_the_generated_table() -> None:
    assert interface_table() in INTERFACE_MD.read_text(encoding="utf-8")
