"""The oracle on emitted files (needs SUMO's netconvert for the road network): every case passes in
every version, and a mutated file fails with a reason that names what is wrong."""

from __future__ import annotations

import copy
import shutil
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest
from lxml import etree
from sovarc.compiler.plan import Sample
from sovarc.targets.openscenario import VERSIONS, asam_qc, check
from sovarc.targets.verdict import Verdict

from tests.targets.openscenario.conftest import Emitter
from tests.targets.openscenario.plans import CASES, clipped_rear_corner, emit_files, straight, with_samples

pytestmark = pytest.mark.slow  # needs SUMO (netconvert writes the .xodr)


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("case", sorted(CASES))
def test_every_case_passes_in_every_version(emitted: Emitter, case: str, version: str) -> None:
    plan, files = emitted(case, version)
    verdict = check(files.xosc, plan)
    assert verdict.passed, verdict.dumps()
    assert (verdict.target, verdict.scenario, verdict.site) == ("openscenario", plan.scenario.name, plan.site)
    checks = {f.check for f in verdict.findings}
    assert {"xsd", "asam_qc", "xodr", "teleports", "speed", "collision_area", "first_contact", "impact_angle"} <= checks
    ran = int(next(f.message for f in verdict.findings if f.check == "asam_qc").split(": ")[1].split()[0])
    assert ran == (5 if version in ("1.0", "1.1") else 17)  # ASAM's reference rules are defined from 1.2 on
    assert verdict.facts["first_contact_time"] == pytest.approx(plan.impact.time, abs=0.05)
    assert verdict.facts["version"] == f"1.{version[-1]}"


def test_without_a_plan_the_verdict_is_named_from_the_file(emitted: Emitter) -> None:
    plan, files = emitted("rear_end")
    verdict = check(files.xosc)
    assert verdict.passed
    assert (verdict.scenario, verdict.site) == (plan.scenario.name, plan.site)
    assert verdict.facts["victim_face"] == "rear" and verdict.facts["striker_face"] == "front"


# --- mutated files -------------------------------------------------------------------


def mutated(emitted: Emitter, tmp_path: Path, case: str, change: Callable[[etree._Element], None]) -> Verdict:
    """Copy an emitted scenario (and its road network), change the .xosc, and judge it."""
    _, files = emitted(case)
    shutil.copy(files.xodr, tmp_path / files.xodr.name)
    doc = etree.parse(str(files.xosc))
    change(doc.getroot())
    target = tmp_path / "scenario.xosc"
    doc.write(str(target), xml_declaration=True, encoding="UTF-8")
    return check(target)


def failed(verdict: Verdict) -> dict[str, str]:
    assert not verdict.passed
    return {f.check: f.message for f in verdict.failures}


def _param(root: etree._Element, name: str, value: str) -> None:
    root.find(f"ParameterDeclarations/ParameterDeclaration[@name='{name}']").set("value", value)


def _vertices(root: etree._Element, entity: str) -> list[etree._Element]:
    group = root.find(f".//ManeuverGroup[@name='{entity}_group']")
    return group.findall(".//Vertex")


def test_a_schema_violation_is_named_with_its_line(emitted: Emitter, tmp_path: Path) -> None:
    def drop_category(root: etree._Element) -> None:
        del root.find("Entities/ScenarioObject/Vehicle").attrib["vehicleCategory"]

    message = failed(mutated(emitted, tmp_path, "t_bone", drop_category))["xsd"]
    assert message.startswith("not valid OpenSCENARIO 1.3: line ")
    assert "vehicleCategory" in message


def test_a_header_that_names_another_version_fails_that_version_s_schema(emitted: Emitter, tmp_path: Path) -> None:
    older = failed(mutated(emitted, tmp_path, "t_bone", lambda r: r.find("FileHeader").set("revMinor", "0")))
    assert older["xsd"].startswith("not valid OpenSCENARIO 1.0: line ")
    assert "Element 'Vehicle', attribute 'mass'" in older["xsd"]  # a 1.1 attribute
    unknown = failed(mutated(emitted, tmp_path, "t_bone", lambda r: r.find("FileHeader").set("revMinor", "9")))
    assert unknown["xsd"] == "OpenSCENARIO 1.9 is not a version the oracle knows (1.0, 1.1, 1.2, 1.3)"


def test_an_undeclared_entity_fails_asam_s_reference_rule_with_its_line(emitted: Emitter, tmp_path: Path) -> None:
    def rename_actor(root: etree._Element) -> None:
        root.find(".//ManeuverGroup/Actors/EntityRef").set("entityRef", "V9")

    message = failed(mutated(emitted, tmp_path, "t_bone", rename_actor))["asam_qc"]
    assert message.startswith("ASAM Quality Checker: 1 issue(s): reference_control.resolvable_entity_references:")
    assert "<EntityRef>" in message and "line " in message


def test_two_events_of_one_name_on_a_level_fail_asam_s_uniqueness_rule(emitted: Emitter, tmp_path: Path) -> None:
    def twin_events(root: etree._Element) -> None:
        maneuver = root.find(".//Maneuver")
        maneuver.append(copy.deepcopy(maneuver.find("Event")))

    message = failed(mutated(emitted, tmp_path, "t_bone", twin_events))["asam_qc"]
    assert "reference_control.unique_element_names_on_same_level" in message


def test_without_asam_s_checker_the_finding_says_how_to_install_it(
    emitted: Emitter, monkeypatch: pytest.MonkeyPatch
) -> None:
    _, files = emitted("t_bone")
    monkeypatch.setattr(asam_qc, "_bundle", lambda: None)
    finding = asam_qc.qc_finding(files.xosc)
    assert not finding.passed
    assert finding.message.endswith("pip install asam-qc-openscenarioxml")


def test_a_victim_that_arrives_late_misses_the_collision_area(emitted: Emitter, tmp_path: Path) -> None:
    def delay_victim(root: etree._Element) -> None:
        for vertex in _vertices(root, "V2"):
            vertex.set("time", f"{float(vertex.get('time')) + 1.0:g}")

    reasons = failed(mutated(emitted, tmp_path, "t_bone", delay_victim))
    assert "not both in C_A: V2 is" in reasons["collision_area"]
    assert "starts at t=1 s, not at 0" in reasons["teleports"]


def test_a_jump_inside_a_trajectory_breaks_the_speed_limit(emitted: Emitter, tmp_path: Path) -> None:
    def jump(root: etree._Element) -> None:
        world = _vertices(root, "V1")[10].find(".//WorldPosition")
        world.set("x", f"{float(world.get('x')) + 20:g}")

    reasons = failed(mutated(emitted, tmp_path, "t_bone", jump))
    assert reasons["speed"].startswith("V1 moves at 200.") and "above its limit 22.389 m/s" in reasons["speed"]
    assert reasons["acceleration"].startswith("V1 accelerates at")


def test_a_small_kink_is_an_acceleration_the_car_cannot_make(emitted: Emitter, tmp_path: Path) -> None:
    def kink(root: etree._Element) -> None:
        world = _vertices(root, "V2")[5].find(".//WorldPosition")
        world.set("x", f"{float(world.get('x')) + 0.3:g}")

    reasons = failed(mutated(emitted, tmp_path, "t_bone", kink))
    assert set(reasons) == {"acceleration"}
    assert "V2 accelerates at" in reasons["acceleration"] and "above 6" in reasons["acceleration"]


def test_a_teleport_after_the_start_is_refused(emitted: Emitter, tmp_path: Path) -> None:
    def add_teleport(root: etree._Element) -> None:
        action = root.find(".//ManeuverGroup[@name='V1_group']//Action")
        teleport = etree.fromstring(
            '<PrivateAction><TeleportAction><Position><WorldPosition x="0" y="0"/></Position></TeleportAction>'
            "</PrivateAction>"
        )
        action.replace(action.find("PrivateAction"), teleport)  # instead of following its trajectory

    reasons = failed(mutated(emitted, tmp_path, "t_bone", add_teleport))
    assert reasons["teleports"] == "TeleportAction after the start (in the Story) for V1"
    assert reasons["trajectories"] == "V1 has no FollowTrajectoryAction; the oracle expects exactly one"


def test_an_init_position_away_from_the_trajectory_is_a_jump(emitted: Emitter, tmp_path: Path) -> None:
    def move_start(root: etree._Element) -> None:
        world = root.find("Storyboard/Init/Actions/Private[@entityRef='V2']//WorldPosition")
        world.set("y", f"{float(world.get('y')) + 3:g}")

    reasons = failed(mutated(emitted, tmp_path, "t_bone", move_start))
    assert reasons == {"teleports": "V2 jumps 3.00 m from its Init position to its trajectory"}


def test_the_wrong_crash_type_fails_angle_and_faces(emitted: Emitter, tmp_path: Path) -> None:
    reasons = failed(mutated(emitted, tmp_path, "t_bone", lambda r: _param(r, "sovarc_crash_type", "rear_end")))
    assert reasons["impact_angle"] == "90° between the headings at impact; a rear_end crash needs 0° to 45°"
    assert reasons["impact_faces"] == "the victim V2 is hit on its right, not its rear"


def test_swapped_striker_and_victim_hit_with_the_wrong_face(emitted: Emitter, tmp_path: Path) -> None:
    def swap(root: etree._Element) -> None:
        _param(root, "sovarc_striker", "V2")
        _param(root, "sovarc_victim", "V1")

    reasons = failed(mutated(emitted, tmp_path, "t_bone", swap))
    assert reasons == {
        "impact_faces": "the striker V2 hits with its right, not its front; the victim V1 is hit on its front, not "
        "its left or right"
    }


def test_an_impact_declared_too_early_finds_the_bodies_away_from_the_collision_area(
    emitted: Emitter, tmp_path: Path
) -> None:
    verdict = mutated(emitted, tmp_path, "head_on", lambda r: _param(r, "sovarc_impact_time", "2"))
    reasons = failed(verdict)
    assert set(reasons) == {"collision_area"}  # they still meet in C_A, a second later
    assert reasons["collision_area"] == "at t=2 s not both in C_A: V1 is 26.82 m from it; V2 is 20.12 m from it"
    assert verdict.facts["first_contact_time"] == pytest.approx(3.0, abs=0.03)


def test_a_missing_stop_trigger_would_let_a_player_run_forever(emitted: Emitter, tmp_path: Path) -> None:
    def drop_stop(root: etree._Element) -> None:
        storyboard = root.find("Storyboard")
        storyboard.remove(storyboard.find("StopTrigger"))

    reasons = failed(mutated(emitted, tmp_path, "rear_end", drop_stop))
    assert reasons == {"stop_trigger": "no simulation-time StopTrigger: a player may run forever"}


def test_a_missing_road_network_is_named(emitted: Emitter, tmp_path: Path) -> None:
    reasons = failed(mutated(emitted, tmp_path, "rear_end", lambda r: r.find(".//LogicFile").set("filepath", "x.xodr")))
    assert reasons == {"xodr": "road network x.xodr not found beside the scenario"}


def test_an_undeclared_impact_stops_the_kinematic_check(emitted: Emitter, tmp_path: Path) -> None:
    def drop(root: etree._Element) -> None:
        declarations = root.find("ParameterDeclarations")
        declarations.remove(declarations.find("ParameterDeclaration[@name='sovarc_impact_time']"))

    reasons = failed(mutated(emitted, tmp_path, "rear_end", drop))
    assert reasons == {"pair": "the file does not declare sovarc_impact_time"}


def test_a_file_that_is_not_xml_is_one_clear_finding(tmp_path: Path) -> None:
    broken = tmp_path / "scenario.xosc"
    broken.write_text("<OpenSCENARIO><FileHeader", encoding="utf-8")
    verdict = check(broken)
    assert [f.check for f in verdict.findings] == ["xml"]
    assert verdict.findings[0].message.startswith("scenario.xosc is not well-formed XML")


def test_a_plan_whose_pair_touches_too_early_fails(tmp_path: Path) -> None:
    plan = CASES["rear_end"]()
    # The stopped victim stands 8 m further back: the striker reaches it about 0.36 s early.
    early = with_samples(plan, "V2", lambda s: replace(s, x=s.x - 8.0))
    verdict = check(emit_files(early, tmp_path).xosc, early)
    reasons = {f.check: f.message for f in verdict.failures}
    assert reasons["first_contact"].startswith("V1 and V2 first touch at t=2.6")
    assert reasons["first_contact"].endswith(
        "before the impact t=3 s, outside C_A: V1 is 7.60 m from it; V2 is 3.40 m from it"
    )
    assert verdict.facts["victim_face"] == "rear"  # the crash is judged where it happens


def test_a_pair_that_overlaps_from_the_start_fails(tmp_path: Path) -> None:
    plan = CASES["rear_end"]()
    start = plan.trajectory("V1").samples[0]
    # The stopped victim stands where the striker starts: the two are one body at t=0.
    stacked = with_samples(plan, "V2", lambda s: replace(s, x=start.x + 1.0))
    reasons = {f.check: f.message for f in check(emit_files(stacked, tmp_path).xosc, stacked).failures}
    assert reasons["first_contact"].startswith(
        "V1 and V2 first touch at t=0.00 s, before the impact t=3 s, outside C_A"
    )


def test_bodies_that_touch_but_never_overlap_are_no_collision_for_a_player(tmp_path: Path) -> None:
    plan = CASES["rear_end"]()
    x_stop = plan.impact.point[0] - 0.005  # the striker halts 5 mm short of the victim's rear
    halted = with_samples(plan, "V1", lambda s: replace(s, x=min(s.x, x_stop)))
    reasons = {f.check: f.message for f in check(emit_files(halted, tmp_path).xosc, halted).failures}
    assert (
        reasons["overlap"]
        == "the bounding boxes of V1 and V2 never overlap after the impact: a player sees no collision"
    )
    assert "first_contact" not in reasons  # 5 mm is a touch


def test_an_oblique_corner_that_touches_first_inside_the_collision_area_passes(tmp_path: Path) -> None:
    """A slow striker 20 degrees off square: its front-left corner meets the victim's side about
    0.35 s before its bumper centre does, 0.3 m from C_A's centre. That is the planned crash."""
    plan = CASES["t_bone"]()
    t_hit, (x, y) = plan.impact.time, plan.impact.point
    oblique = with_samples(plan, "V1", lambda s: Sample(s.t, *straight(x, y, 20.0, 1.0, t_hit)(s.t)))
    verdict = check(emit_files(oblique, tmp_path).xosc, oblique)
    assert verdict.passed, verdict.dumps()
    assert verdict.facts["first_contact_time"] == pytest.approx(t_hit - 0.33, abs=0.03)
    assert verdict.facts["striker_face"] == "front-left" and verdict.facts["victim_face"] == "front-right"


def test_a_striker_that_clips_the_rear_corner_before_the_collision_area_fails(tmp_path: Path) -> None:
    """One class of disagreement between the oracles on the ground truth: a striker closing from behind at a shallow
    angle meets the victim's rear corner before C_A. A player records the crash there and then, so the
    file does not crash where the plan says, though both bodies do reach C_A at the impact time."""
    plan = clipped_rear_corner()
    verdict = check(emit_files(plan, tmp_path).xosc, plan)
    reasons = failed(verdict)
    assert set(reasons) == {"first_contact", "impact_faces"}  # and its rear is struck, not its side
    assert reasons["impact_faces"] == (
        "the victim V2 is hit on its rear-right corner, struck on its rear, not its left or right"
    )
    assert reasons["first_contact"] == (
        "V1 and V2 first touch at t=3.72 s, before the impact t=4 s, outside C_A: V1 is 3.36 m from it"
    )
    assert (verdict.facts["striker_face"], verdict.facts["victim_face"]) == ("front-left", "rear-right")
    assert verdict.facts["relative_heading"] == pytest.approx(8.0, abs=0.1)


def test_bystanders_that_collide_before_the_impact_are_found(tmp_path: Path) -> None:
    plan = CASES["t_bone"]()
    v1 = plan.trajectory("V1")
    ghost = replace(v1, participant="V3", samples=tuple(replace(s, x=s.x + 1.0) for s in v1.samples))
    crowded = replace(plan, trajectories=(*plan.trajectories, ghost))
    verdict = check(emit_files(crowded, tmp_path).xosc, crowded)
    reasons = {f.check: f.message for f in verdict.failures}
    assert reasons["other_contacts"] == "V1 and V3 collide at t=0.00 s, before the impact"


def test_sample_helper_keeps_other_participants() -> None:
    plan = CASES["t_bone"]()
    moved = with_samples(plan, "V1", lambda s: Sample(s.t, s.x + 1, s.y, s.heading, s.speed))
    assert moved.trajectory("V2") == plan.trajectory("V2")
    assert moved.trajectory("V1").samples[0].x == plan.trajectory("V1").samples[0].x + 1
